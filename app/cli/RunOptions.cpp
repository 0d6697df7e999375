// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RunOptions.h"

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addRunOptions(CLI::App& cmd, RunArgs& a) {
  addTimeStepOption(cmd, a.options.timeStep);
  addScenarioOptions(cmd, a.scenario);
  addEnumOption(cmd, simulation_option::kSolver, a.solver);
  addEnumOption(cmd, simulation_option::kTangent, a.tangent);
  addNumberOption(cmd, simulation_option::kTolerance, a.options.tolerance);
  addNumberOption(cmd, simulation_option::kGuessSolutions, a.options.guessSolutions);
  addNumberOption(cmd, simulation_option::kCoarseReuse, a.options.coarseReuse);
  addNumberOption(cmd, simulation_option::kMaxIterations, a.options.maxIterations);
  addNumberOption(cmd, simulation_option::kFriction, a.options.friction);
  addNumberOption(cmd, simulation_option::kFloorStiffness, a.options.floorStiffness);
  addEnumOption(cmd, simulation_option::kCoarseOperators, a.coarseOperators);
  addEnumOption(cmd, simulation_option::kCoarseLevels, a.coarseLevels);
  addMaterialOptions(cmd, a.material);
}

void addPrintRunFlag(CLI::App& cmd, bool& printRun) {
  cmd.add_flag("--print-run", printRun,
               "print the run these options describe (JSON: every setting, after the dataset's "
               "config and the defaults) and exit without running it");
}

void requireOutputOrPrintRun(const std::filesystem::path& output, bool printRun) {
  if (output.empty() && !printRun) throw Error("--output is required (or --print-run)");
}

void checkRunOptions(const RunArgs& a, const CLI::App& cmd) {
  using namespace simulation_option;
  if (fromName<SolverKind>(a.solver) == SolverKind::ConjugateGradient)
    for (const char* option : {kCoarseReuse.flag, kCoarseOperators.flag, kCoarseLevels.flag})
      if (cmd.count(option) > 0)
        throw Error(std::string(option) + ": applies to the multigrid solver (" + kSolver.flag +
                    " multigrid or auto), not to cg");
}

void applyRunOptions(const RunArgs& a, const CLI::App& cmd, Index nodeCount, RunRequest& request) {
  using namespace simulation_option;
  request.names = OptionNames::Flags;
  SimulationOptions& s = request.settings;
  const auto given = [&](const NumberOption& option) { return givenName(cmd, option).has_value(); };
  const auto chosen = [&](const auto& option) { return cmd.count(option.flag) > 0; };
  if (given(kTimeStep)) s.timeStep = a.options.timeStep;
  if (given(kTolerance)) s.tolerance = a.options.tolerance;
  if (given(kGuessSolutions)) s.guessSolutions = a.options.guessSolutions;
  if (given(kCoarseReuse)) s.coarseReuse = a.options.coarseReuse;
  if (given(kMaxIterations)) s.maxIterations = a.options.maxIterations;
  if (given(kFriction)) s.friction = a.options.friction;
  if (given(kFloorStiffness)) s.floorStiffness = a.options.floorStiffness;
  if (chosen(kSolver)) s.solver = fromName<SolverKind>(a.solver);
  if (chosen(kTangent)) s.tangent = fromName<Tangent>(a.tangent);
  if (chosen(kCoarseOperators)) s.coarseOperators = fromName<CoarseOperators>(a.coarseOperators);
  if (chosen(kCoarseLevels)) s.coarseLevels = fromName<CoarseLevels>(a.coarseLevels);
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (a.material.values[i]) request.material.values[i] = a.material.values[i];
  fillScenario(cmd, a.scenario, nodeCount, request);
}

RunRequest runRequest(const RunArgs& a, const CLI::App& cmd, const Dataset& dataset, int level,
                      const std::string& datasetName) {
  RunRequest request;
  request.datasetName = datasetName;
  request.level = level;
  applyRunOptions(a, cmd, dataset.mesh.levels[static_cast<std::size_t>(level)].nodeCount, request);
  return request;
}

RunSpec runSpec(const RunArgs& a, const CLI::App& cmd, const Dataset& dataset, int level,
                const std::string& datasetName) {
  return resolveRun(runRequest(a, cmd, dataset, level, datasetName), dataset.mesh, dataset.config);
}

}  // namespace tetskin::cli
