// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/IsolatedJobs.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>

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

// Child side: run the job and stream the result to the parent, then exit
// without running the parent's destructors.
[[noreturn]] void runChild(const MeshJob& job, int fd) {
  // Meshers print progress (Netgen always does); keep the terminal clean.
  if (const int devnull = ::open("/dev/null", O_WRONLY); devnull >= 0) ::dup2(devnull, 1);
  std::string error;
  try {
    const TetMesh mesh = job();
    const char ok = 0;
    const std::int64_t counts[2] = {mesh.nodeCount(), mesh.elementCount()};
    writeAll(fd, &ok, 1);
    writeAll(fd, counts, sizeof counts);
    writeAll(fd, mesh.nodes.data(), sizeof(double) * static_cast<std::size_t>(mesh.nodes.size()));
    writeAll(fd, mesh.elements.data(),
             sizeof(int) * static_cast<std::size_t>(mesh.elements.size()));
    ::close(fd);
    ::_exit(0);
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

IsolatedResult decode(const std::string& data, int status) {
  IsolatedResult r;
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
  std::int64_t counts[2];
  if (data.size() < 1 + sizeof counts) {
    r.error = "the mesher's result was truncated";
    return r;
  }
  std::memcpy(counts, data.data() + 1, sizeof counts);
  const std::size_t nodeBytes = sizeof(double) * 3 * static_cast<std::size_t>(counts[0]);
  const std::size_t elementBytes = sizeof(int) * 4 * static_cast<std::size_t>(counts[1]);
  if (counts[0] < 0 || counts[1] < 0 ||
      data.size() != 1 + sizeof counts + nodeBytes + elementBytes) {
    r.error = "the mesher's result was truncated";
    return r;
  }
  r.mesh.nodes.resize(counts[0], 3);
  r.mesh.elements.resize(counts[1], 4);
  std::memcpy(r.mesh.nodes.data(), data.data() + 1 + sizeof counts, nodeBytes);
  std::memcpy(r.mesh.elements.data(), data.data() + 1 + sizeof counts + nodeBytes, elementBytes);
  r.ok = true;
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

}  // namespace

std::vector<IsolatedResult> runIsolated(
    const std::vector<MeshJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedResult&)>& onDone,
    const std::function<bool()>& cancelled) {
  std::vector<IsolatedResult> results(jobs.size());
  std::vector<Running> running;
  std::size_t next = 0;
  parallel = std::max(1, parallel);
  const auto timeout = std::chrono::duration<double>(timeoutSeconds);

  auto finish = [&](Running& r, const IsolatedResult& result) {
    results[r.job] = result;
    results[r.job].seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    if (onDone) onDone(r.job, results[r.job]);
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
      int fds[2];
      if (::pipe(fds) != 0) throw Error("cannot create a pipe for the mesher process");
      std::fflush(nullptr);  // do not duplicate buffered output into the child
      const pid_t pid = ::fork();
      if (pid < 0) throw Error("cannot start a mesher process");
      if (pid == 0) {
        ::close(fds[0]);
        runChild(jobs[next], fds[1]);
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
      IsolatedResult result = decode(r.data, status);
      if (!r.eof) {
        result = {};
        result.error = "the mesher did not finish within " +
                       std::to_string(static_cast<int>(timeoutSeconds)) + " s and was stopped";
      }
      finish(r, result);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
  return results;
}

}  // namespace tetskin
