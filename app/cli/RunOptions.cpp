// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RunOptions.h"

#include "OptionChecks.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addRunOptions(CLI::App& cmd, RunArgs& a) {
  addTimeStepOption(cmd, a.options.timeStep);
  addScenarioOptions(cmd, a.scenario);
  addEnumOption<SolverKind>(cmd, "--solver", "", a.solver);
  addEnumOption<Tangent>(cmd, "--tangent", "the implicit step's stiffness: ", a.tangent);
  addNumberOption(cmd, simulation_option::kTolerance, a.options.tolerance);
  addNumberOption(cmd, simulation_option::kGuessSolutions, a.options.guessSolutions);
  addNumberOption(cmd, simulation_option::kCoarseReuse, a.options.coarseReuse);
  addEnumOption<CoarseOperators>(cmd, "--coarse-operators", "multigrid: ", a.coarseOperators);
  addEnumOption<CoarseLevels>(cmd, "--coarse-levels", "multigrid: ", a.coarseLevels);
  addMaterialOptions(cmd, a.material);
}

void checkRunOptions(const RunArgs& a, const CLI::App& cmd) {
  if (fromName<SolverKind>(a.solver) == SolverKind::ConjugateGradient)
    for (const char* option : {"--coarse-reuse", "--coarse-operators", "--coarse-levels"})
      if (cmd.count(option) > 0)
        throw Error(std::string(option) +
                    ": applies to the multigrid solver (--solver multigrid or auto), not to cg");
}

RunSpec runSpec(const RunArgs& a, const CLI::App& cmd, const Dataset& dataset, int level,
                const std::string& datasetName) {
  SimulationOptions options = a.options;
  options.solver = fromName<SolverKind>(a.solver);
  options.tangent = fromName<Tangent>(a.tangent);
  options.coarseOperators = fromName<CoarseOperators>(a.coarseOperators);
  options.coarseLevels = fromName<CoarseLevels>(a.coarseLevels);
  options.material = materialOf(a.material, dataset.config.elasticity);
  options =
      withGravityAndFloor(uprightAlong(upAxisOf(a.scenario, dataset.config), options), a.scenario);
  RunSpec spec;
  spec.level = level;
  spec.options = options;
  spec.scenario = a.scenario.name;
  spec.parameters = scenarioParameters(cmd, a.scenario, extractLevel(dataset.mesh, level).nodes);
  spec.datasetName = datasetName;
  return spec;
}

}  // namespace tetskin::cli
