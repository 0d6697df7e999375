// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Runs mesher calls in child processes, several at a time. A mesher that
// throws, aborts, crashes or hangs on one candidate (TetGen and Netgen can,
// on hostile input) is reported as failed; the tool itself goes on.

#include <functional>
#include <string>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

// Thrown when a caller cancels long work (a build from the GUI).
struct Cancelled : Error {
  Cancelled() : Error("cancelled") {}
};

struct IsolatedResult {
  bool ok = false;
  TetMesh mesh;
  std::string error;  // why it failed: the exception text, the signal, or the timeout
  double seconds = 0;
};

using MeshJob = std::function<TetMesh()>;

// Runs every job in a forked child process, at most `parallel` at once. A job
// still running after `timeoutSeconds` is killed. `onDone(index, result)` runs
// in the calling process as each job ends. Results are in job order.
// `cancelled`, polled about every 0.1 s: when it returns true every running
// child is killed and Cancelled is thrown.
std::vector<IsolatedResult> runIsolated(
    const std::vector<MeshJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedResult&)>& onDone = {},
    const std::function<bool()>& cancelled = {});

}  // namespace tetskin
