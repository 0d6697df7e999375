// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Runs mesher (and wrap) calls in child processes, several at a time. A
// mesher that throws, aborts, crashes or hangs on one candidate (TetGen and
// Netgen can, on hostile input) is reported as failed; the tool itself goes
// on.

#include <functional>
#include <string>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

// Thrown when a caller cancels long work (a build from the GUI).
struct Cancelled : Error {
  Cancelled() : Error("cancelled") {}
};

// What one isolated job gave: its mesh (a TetMesh from a mesher, a
// SurfaceMesh from the wrap), or why it failed.
template <typename Mesh>
struct IsolatedOutcome {
  bool ok = false;
  Mesh mesh;
  std::string error;  // why it failed: the exception text, the signal, or the timeout
  double seconds = 0;
  bool skipped = false;  // never started: `skip` gave `error` as the reason
};
using IsolatedResult = IsolatedOutcome<TetMesh>;
using IsolatedSurface = IsolatedOutcome<SurfaceMesh>;

using MeshJob = std::function<TetMesh()>;
using SurfaceJob = std::function<SurfaceMesh()>;

// Runs every job in a forked child process, at most `parallel` at once. A job
// still running after `timeoutSeconds` is killed. `onDone(index, result)` runs
// in the calling process as each job ends. Results are in job order.
// `cancelled`, polled about every 0.1 s: when it returns true every running
// child is killed and Cancelled is thrown. `skip(index)`, asked just before
// a job would start (so it sees the results of the jobs ended so far): a
// non-empty reason leaves the job unstarted, its result `skipped` with that
// reason as its error (onDone is not called for it). A surface job's result
// keeps its positions and triangles only.
using SkipJob = std::function<std::string(std::size_t)>;
std::vector<IsolatedResult> runIsolated(
    const std::vector<MeshJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedResult&)>& onDone = {},
    const std::function<bool()>& cancelled = {}, const SkipJob& skip = {});
std::vector<IsolatedSurface> runIsolated(
    const std::vector<SurfaceJob>& jobs, int parallel, double timeoutSeconds,
    const std::function<void(std::size_t, const IsolatedSurface&)>& onDone = {},
    const std::function<bool()>& cancelled = {});

}  // namespace tetskin
