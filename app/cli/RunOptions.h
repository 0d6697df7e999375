// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The options of a simulated run that `simulate` and `compare` share: the
// time step, the scenario, the solver and its settings, the material; and
// the run (RunSpec) they describe on a level of a dataset.

#include <CLI/CLI.hpp>
#include <string>

#include "MaterialOptions.h"
#include "ScenarioOptions.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::cli {

struct RunArgs {
  std::string solver = toString(SolverKind::Automatic),
              coarseOperators = toString(SimulationOptions{}.coarseOperators),
              coarseLevels = toString(SimulationOptions{}.coarseLevels),
              tangent = toString(SimulationOptions{}.tangent);
  ScenarioArgs scenario;
  SimulationOptions options;
  MaterialArgs material;  // over the config's elasticity
};

// Adds --dt, the scenario options, --solver, --tangent, the solver's
// settings and the material options to `cmd`.
void addRunOptions(CLI::App& cmd, RunArgs& args);

// Throws Error for a multigrid setting given with --solver cg (checked
// before any work, as a typo would be).
void checkRunOptions(const RunArgs& args, const CLI::App& cmd);

// The run the options describe on `level` of `dataset` (named
// `datasetName` in errors).
RunSpec runSpec(const RunArgs& args, const CLI::App& cmd, const Dataset& dataset, int level,
                const std::string& datasetName);

}  // namespace tetskin::cli
