// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A simulation run's steps as a CSV table (`tetskin simulate --log`), for
// plotting energy, support forces, iterations and step times: one row for
// the start (step 0) and one per step.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

struct StepLogRow {
  Index step = 0;      // 0: the start, before any step
  double time = 0;     // seconds of simulated time after the step
  std::string solver;  // "cg" or "multigrid"; empty for the start
  int iterations = 0;
  double residual = 0;  // the solve's relative residual
  int contacts = 0;     // nodes in contact with the floor
  // Wall-clock seconds of the step: element pass, preconditioner setup,
  // solve, and the whole step.
  double assemblySeconds = 0, setupSeconds = 0, solveSeconds = 0, stepSeconds = 0;
  // Joules after the step (gravitational: from whatever zero the caller
  // measures it; simulate's log from the rest shape, as Simulation does).
  // load: the surface loads' potential (zero without them).
  double kinetic = 0, elastic = 0, gravitational = 0, load = 0;
  // Newtons after the step: the supports' reactions summed over the
  // prescribed nodes (zero where none is).
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
};

// The header line of the table (without its newline).
std::string stepLogHeader();

// Writes the table atomically (a temporary file renamed over `path`):
// stepLogHeader() and one line per row. Times in milliseconds; the start's
// solver, iteration, residual and time columns are empty.
void writeStepLog(const std::filesystem::path& path, const std::vector<StepLogRow>& rows);

}  // namespace tetskin
