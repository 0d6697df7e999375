// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The options of a simulated run that `simulate` and `compare` share: the
// time step, the scenario, the solver and its settings, the material; and
// the run (RunSpec) they describe on a level of a dataset.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "MaterialOptions.h"
#include "ScenarioOptions.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::cli {

struct RunArgs {
  std::string solver = toString(defaultRunSettings().solver),
              coarseOperators = toString(defaultRunSettings().coarseOperators),
              coarseLevels = toString(defaultRunSettings().coarseLevels),
              tangent = toString(defaultRunSettings().tangent);
  ScenarioArgs scenario;
  SimulationOptions options = defaultRunSettings();  // the numbers given
  MaterialOverrides material;                        // over the config's elasticity
};

// Adds --time-step, the scenario options, --solver, --tangent, the solver's
// settings and the material options to `cmd`.
void addRunOptions(CLI::App& cmd, RunArgs& args);

// Adds --print-run: print the run the options describe (runSpecJson) and
// exit without running it.
void addPrintRunFlag(CLI::App& cmd, bool& printRun);
// Throws Error for a command given neither -o nor --print-run.
void requireOutputOrPrintRun(const std::filesystem::path& output, bool printRun);

// Throws Error for a multigrid setting given with --solver cg (checked
// before any work, as a typo would be).
void checkRunOptions(const RunArgs& args, const CLI::App& cmd);

// Sets in `request` the options given on the command line (the rest stays
// as `request` has it: the defaults, or a scene's values), for a level of
// `nodeCount` nodes; errors name the flags.
void applyRunOptions(const RunArgs& args, const CLI::App& cmd, Index nodeCount,
                     RunRequest& request);

// The run the options ask for on `level` of `dataset` (named
// `datasetName` in errors), and the run it is (resolveRun).
RunRequest runRequest(const RunArgs& args, const CLI::App& cmd, const Dataset& dataset, int level,
                      const std::string& datasetName);
RunSpec runSpec(const RunArgs& args, const CLI::App& cmd, const Dataset& dataset, int level,
                const std::string& datasetName);

}  // namespace tetskin::cli
