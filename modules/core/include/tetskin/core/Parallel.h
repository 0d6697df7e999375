// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The kernels' parallel loops, in one place: a loop over an index range in
// pieces, and a reduction whose result is the same bits on any number of
// threads. They run on TBB (include this only from a module that links
// TBB::tbb), except in a ThreadSanitizer build: Debian's TBB is not
// instrumented, so TSan cannot see how its tasks hand work over and reports
// TBB's own internals by the hundred; there each loop runs its pieces on
// std::threads, whose start and join TSan does see, so what it reports is a
// race in a loop's body, which is ours (doc/dev/testing.md, "Reliability").

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <thread>
#include <utility>
#include <vector>

#if defined(__SANITIZE_THREAD__)
#define TETSKIN_PARALLEL_ON_STD_THREADS 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define TETSKIN_PARALLEL_ON_STD_THREADS 1
#endif
#endif

namespace tetskin {

// Indices [begin, end) of a loop: one piece of the whole a body is given.
template <typename I>
class IndexRange {
 public:
  IndexRange(I begin, I end) : begin_(begin), end_(end) {}
  I begin() const { return begin_; }
  I end() const { return end_; }
  I size() const { return end_ - begin_; }

 private:
  I begin_, end_;
};

// body(const IndexRange<I>&) for pieces covering [begin, end) once, of
// `grain` indices or more where there are that many, in parallel.
template <typename I, typename Body>
void parallelFor(I begin, I end, I grain, const Body& body) {
  if (end <= begin) return;
#ifdef TETSKIN_PARALLEL_ON_STD_THREADS
  // Four pieces (fewer where the range is short), whatever the machine has:
  // concurrency, not speed, is what this build is for.
  const I pieces = std::clamp<I>((end - begin) / std::max<I>(grain, 1), 1, 4);
  const I step = (end - begin + pieces - 1) / pieces;
  std::vector<std::thread> threads;
  for (I first = begin + step; first < end; first += step)
    threads.emplace_back(
        [&body, first, end, step] { body(IndexRange<I>(first, std::min(end, first + step))); });
  body(IndexRange<I>(begin, std::min(end, begin + step)));
  for (std::thread& t : threads) t.join();
#else
  tbb::parallel_for(tbb::blocked_range<I>(begin, end, grain), [&](const tbb::blocked_range<I>& r) {
    body(IndexRange<I>(r.begin(), r.end()));
  });
#endif
}

namespace detail {
// TBB's deterministic reduction, spelled out: halve the range until a half
// has `grain` indices or fewer, reduce each from `identity`, join the halves
// left to right; the top `depth` halvings run their right halves on threads.
template <typename I, typename Value, typename Body, typename Join>
Value reduceHalves(I begin, I end, I grain, const Value& identity, const Body& body,
                   const Join& join, int depth) {
  if (end - begin <= grain) return body(IndexRange<I>(begin, end), identity);
  const I middle = begin + (end - begin) / 2;
  if (depth <= 0)
    return join(reduceHalves(begin, middle, grain, identity, body, join, 0),
                reduceHalves(middle, end, grain, identity, body, join, 0));
  Value right = identity;
  std::thread thread(
      [&] { right = reduceHalves(middle, end, grain, identity, body, join, depth - 1); });
  Value left = reduceHalves(begin, middle, grain, identity, body, join, depth - 1);
  thread.join();
  return join(std::move(left), std::move(right));
}
}  // namespace detail

// The reduction of [begin, end): body(const IndexRange<I>&, Value partial)
// returns partial plus the piece's contribution, join(left, right) adds two
// partials. The pieces and the order of the joins depend only on the range
// and `grain`, never on the threads: the same input gives the same bits.
template <typename I, typename Value, typename Body, typename Join>
Value parallelDeterministicReduce(I begin, I end, I grain, const Value& identity, const Body& body,
                                  const Join& join) {
  if (end <= begin) return identity;
#ifdef TETSKIN_PARALLEL_ON_STD_THREADS
  return detail::reduceHalves(begin, end, std::max<I>(grain, 1), identity, body, join, 2);
#else
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<I>(begin, end, grain), identity,
      [&](const tbb::blocked_range<I>& r, Value partial) {
        return body(IndexRange<I>(r.begin(), r.end()), std::move(partial));
      },
      join);
#endif
}

}  // namespace tetskin
