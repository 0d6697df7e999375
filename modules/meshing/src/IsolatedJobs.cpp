// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/IsolatedJobs.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

using Clock = std::chrono::steady_clock;

void writeAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      ::_exit(3);
    }
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

// A job as the child runs it: the result mesh's rows, as bytes.
using ByteJob = std::function<std::string()>;

// A mesh's rows as bytes: the counts of points and cells, the points
// (doubles, 3 a row), the cells (ints, as many a row as the mesh has).
template <typename Cells>
std::string encode(const Points3& points, const Cells& cells) {
  const std::int64_t counts[2] = {points.rows(), cells.rows()};
  std::string bytes(sizeof counts + sizeof(double) * static_cast<std::size_t>(points.size()) +
                        sizeof(int) * static_cast<std::size_t>(cells.size()),
                    '\0');
  char* p = bytes.data();
  std::memcpy(p, counts, sizeof counts);
  p += sizeof counts;
  std::memcpy(p, points.data(), sizeof(double) * static_cast<std::size_t>(points.size()));
  p += sizeof(double) * static_cast<std::size_t>(points.size());
  std::memcpy(p, cells.data(), sizeof(int) * static_cast<std::size_t>(cells.size()));
  return bytes;
}

// The rows back; false when the bytes are not a whole result.
template <typename Cells>
bool decodeRows(const std::string& bytes, Points3& points, Cells& cells) {
  std::int64_t counts[2];
  if (bytes.size() < sizeof counts) return false;
  std::memcpy(counts, bytes.data(), sizeof counts);
  if (counts[0] < 0 || counts[1] < 0) return false;
  const std::size_t pointBytes = sizeof(double) * 3 * static_cast<std::size_t>(counts[0]);
  const std::size_t cellBytes = sizeof(int) * static_cast<std::size_t>(Cells::ColsAtCompileTime) *
                                static_cast<std::size_t>(counts[1]);
  if (bytes.size() != sizeof counts + pointBytes + cellBytes) return false;
  points.resize(counts[0], 3);
  cells.resize(counts[1], Cells::ColsAtCompileTime);
  std::memcpy(points.data(), bytes.data() + sizeof counts, pointBytes);
  std::memcpy(cells.data(), bytes.data() + sizeof counts + pointBytes, cellBytes);
  return true;
}

// The address space each child may take: what the parent already maps,
// plus its share (of `parallel`) of 80% of the machine's memory. A mesher
// that would take more (TetGen refining a bad surface can grow past 7 GB in
// minutes) fails with bad_alloc instead of pushing the machine into the
// OOM killer. 0 (no limit) under AddressSanitizer, which reserves
// terabytes of address space for its shadow memory.
std::uint64_t childAddressSpace(int parallel) {
#if defined(__SANITIZE_ADDRESS__)
  (void)parallel;
  return 0;
#else
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return 0;
  unsigned long long mapped = 0;  // pages the parent maps now
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%llu", &mapped) != 1) mapped = 0;
    std::fclose(statm);
  }
  const double share = 0.8 * static_cast<double>(pages) * static_cast<double>(pageSize) /
                       static_cast<double>(std::max(1, parallel));
  return static_cast<std::uint64_t>(mapped) * static_cast<std::uint64_t>(pageSize) +
         static_cast<std::uint64_t>(share);
#endif
}

// Child side: run the job and stream the result to the parent, then exit
// without running the parent's destructors.
[[noreturn]] void runChild(const ByteJob& job, int fd, std::uint64_t addressSpace) {
  // Meshers print progress (Netgen always does); keep the terminal clean.
  if (const int devnull = ::open("/dev/null", O_WRONLY); devnull >= 0) ::dup2(devnull, 1);
  if (addressSpace > 0) {
    const rlimit limit{addressSpace, addressSpace};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  std::string error;
  try {
    const std::string result = job();
    const char ok = 0;
    writeAll(fd, &ok, 1);
    writeAll(fd, result.data(), result.size());
    ::close(fd);
    ::_exit(0);
  } catch (const std::bad_alloc&) {
    char gib[32];
    std::snprintf(gib, sizeof gib, "%.1f", static_cast<double>(addressSpace) / (1u << 30));
    error = std::string("the mesher ran out of memory (") + (addressSpace > 0 ? gib : "?") +
            " GiB a process; fewer --jobs give each process more)";
  } catch (const std::exception& e) {
    error = e.what();
  } catch (int code) {
    error = "the mesher threw error code " + std::to_string(code);
  } catch (...) {
    error = "the mesher threw an unknown exception";
  }
  const char failed = 1;
  writeAll(fd, &failed, 1);
  writeAll(fd, error.data(), error.size());
  ::close(fd);
  ::_exit(0);
}

// The child's answer: ok with the result's bytes, or the error.
struct ByteResult {
  bool ok = false;
  std::string bytes;
  std::string error;
  double seconds = 0;
  bool skipped = false;
};

ByteResult decode(const std::string& data, int status) {
  ByteResult r;
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    r.error = std::string("the mesher crashed (signal ") + std::to_string(sig) + ", " +
              ::strsignal(sig) + ")";
    return r;
  }
  if (data.empty()) {
    r.error = "the mesher exited with status " + std::to_string(WEXITSTATUS(status)) +
              " without a result";
    return r;
  }
  if (data[0] == 1) {
    r.error = data.substr(1);
    return r;
  }
  r.ok = true;
  r.bytes = data.substr(1);
  return r;
}

struct Running {
  std::size_t job;
  pid_t pid;
  int fd;
  Clock::time_point start;
  std::string data;
  bool eof = false;
};

// The engine of both runIsolated: each job's bytes (or error) handed to
// onDone as the job ends.
void runIsolatedBytes(const std::vector<ByteJob>& jobs, int parallel, double timeoutSeconds,
                      const std::function<void(std::size_t, ByteResult&)>& onDone,
                      const std::function<bool()>& cancelled, const SkipJob& skip) {
  std::vector<Running> running;
  std::size_t next = 0;
  parallel = std::max(1, parallel);
  const std::uint64_t addressSpace = childAddressSpace(parallel);
  const auto timeout = std::chrono::duration<double>(timeoutSeconds);

  auto finish = [&](Running& r, ByteResult& result) {
    result.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    onDone(r.job, result);
  };

  while (next < jobs.size() || !running.empty()) {
    if (cancelled && cancelled()) {
      for (Running& r : running) {
        ::kill(r.pid, SIGKILL);
        int status = 0;
        while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
        }
        ::close(r.fd);
      }
      throw Cancelled();
    }
    while (next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      if (skip) {
        if (std::string reason = skip(next); !reason.empty()) {
          ByteResult skipped;
          skipped.skipped = true;
          skipped.error = std::move(reason);
          onDone(next++, skipped);
          continue;
        }
      }
      int fds[2];
      if (::pipe(fds) != 0) throw Error("cannot create a pipe for the mesher process");
      std::fflush(nullptr);  // do not duplicate buffered output into the child
      const pid_t pid = ::fork();
      if (pid < 0) throw Error("cannot start a mesher process");
      if (pid == 0) {
        ::close(fds[0]);
        runChild(jobs[next], fds[1], addressSpace);
      }
      ::close(fds[1]);
      ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
      running.push_back({next++, pid, fds[0], Clock::now(), {}, false});
    }
    std::vector<pollfd> polls;
    for (const Running& r : running) polls.push_back({r.fd, POLLIN, 0});
    ::poll(polls.data(), polls.size(), 100);
    for (std::size_t i = 0; i < running.size();) {
      Running& r = running[i];
      char buffer[1 << 16];
      for (;;) {
        const ssize_t n = ::read(r.fd, buffer, sizeof buffer);
        if (n > 0) {
          r.data.append(buffer, static_cast<std::size_t>(n));
          continue;
        }
        if (n == 0) r.eof = true;
        break;  // EAGAIN: nothing more for now
      }
      const bool late = Clock::now() - r.start > timeout;
      if (!r.eof && !late) {
        ++i;
        continue;
      }
      if (!r.eof) ::kill(r.pid, SIGKILL);
      int status = 0;
      while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
      }
      ::close(r.fd);
      ByteResult result = decode(r.data, status);
      if (!r.eof) {
        result = {};
        result.error = "the mesher did not finish within " +
                       std::to_string(static_cast<int>(timeoutSeconds)) + " s and was stopped";
      }
      finish(r, result);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
}

// One runIsolated for either kind of mesh: the jobs' meshes as bytes, and
// back.
template <typename Mesh, typename Cells>
std::vector<IsolatedOutcome<Mesh>> runIsolatedMeshes(
    const std::vector<std::function<Mesh()>>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedOutcome<Mesh>&)>& onDone,
    const std::function<bool()>& cancelled, const SkipJob& skip, Points3 Mesh::*points,
    Cells Mesh::*cells) {
  std::vector<ByteJob> byteJobs;
  for (const auto& job : jobs)
    byteJobs.push_back([&job, points, cells] {
      const Mesh mesh = job();
      return encode(mesh.*points, mesh.*cells);
    });
  std::vector<IsolatedOutcome<Mesh>> results(jobs.size());
  runIsolatedBytes(
      byteJobs, parallel, timeoutSeconds,
      [&](std::size_t i, ByteResult& r) {
        IsolatedOutcome<Mesh>& out = results[i];
        out.seconds = r.seconds;
        if (r.skipped) {
          out.skipped = true;
          out.error = r.error;
          return;
        }
        out.ok = r.ok && decodeRows(r.bytes, out.mesh.*points, out.mesh.*cells);
        out.error = r.ok && !out.ok ? "the mesher's result was truncated" : r.error;
        if (onDone) onDone(i, out);
      },
      cancelled, skip);
  return results;
}

}  // namespace

std::vector<IsolatedResult> runIsolated(
    const std::vector<MeshJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedResult&)>& onDone,
    const std::function<bool()>& cancelled, const SkipJob& skip) {
  return runIsolatedMeshes(jobs, parallel, timeoutSeconds, onDone, cancelled, skip, &TetMesh::nodes,
                           &TetMesh::elements);
}

std::vector<IsolatedSurface> runIsolated(
    const std::vector<SurfaceJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedSurface&)>& onDone,
    const std::function<bool()>& cancelled) {
  return runIsolatedMeshes(jobs, parallel, timeoutSeconds, onDone, cancelled, SkipJob(),
                           &SurfaceMesh::positions, &SurfaceMesh::triangles);
}

}  // namespace tetskin
