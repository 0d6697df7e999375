// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Passes over the nodes of a system in parallel, in fixed chunks of
// consecutive nodes, with sums that come out the same bits whichever thread
// runs which chunk: each chunk's partial sum is kept apart and the partials
// are added in chunk order. CG's dot products and the initial guess's small
// Gram matrices use it, so a simulation repeats exactly on any thread count.

#include <algorithm>
#include <vector>

#include "tetskin/core/Parallel.h"
#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

// Sums: a value type with += (an Eigen fixed-size vector or matrix).
template <typename Sums>
class NodeChunks {
 public:
  // (128 nodes: a chunk's 3-vectors, 3 KB each, stay in L1 between the loops
  // of one pass.)
  explicit NodeChunks(Index nodes, Index chunkNodes = 128)
      : nodes_(nodes),
        chunkNodes_(chunkNodes),
        partial_(static_cast<std::size_t>((nodes + chunkNodes - 1) / chunkNodes)) {}

  // body(first, last) handles nodes [first, last) and returns their sums;
  // the total starts from `zero`.
  template <typename Body>
  Sums sum(const Body& body, const Sums& zero) {
    parallelFor<std::size_t>(0, partial_.size(), 1, [&](const auto& range) {
      for (std::size_t c = range.begin(); c != range.end(); ++c) {
        const Index first = static_cast<Index>(c) * chunkNodes_;
        partial_[c] = body(first, std::min(nodes_, first + chunkNodes_));
      }
    });
    Sums total = zero;
    for (const Sums& sums : partial_) total += sums;
    return total;
  }

 private:
  Index nodes_, chunkNodes_;
  std::vector<Sums> partial_;
};

}  // namespace tetskin
