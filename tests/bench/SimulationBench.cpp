// SPDX-License-Identifier: AGPL-3.0-or-later
// Implicit steps per second of the wobble scenario with block-Jacobi CG and
// with multigrid-preconditioned CG, both to the same relative residual, in the
// same run. Prints a table; asserts nothing.
#include <chrono>
#include <cstdio>
#include <thread>

#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

using namespace tetskin;

namespace {

void row(const char* name, const MultiLevelTetMesh& mesh, int level, SolverKind solver, int steps) {
  SimulationOptions options;
  options.solver = solver;
  options.tolerance = 1e-6;
  Simulation sim(mesh, level, options);
  auto scenario = makeScenario("wobble");
  scenario->setUp(sim);
  for (int i = 0; i < 2; ++i) {  // warm up: one-time setup (e.g. Galerkin streams) is not timed
    scenario->beforeStep(sim, sim.state().time);
    sim.step();
  }
  double assembly = 0, setup = 0, solve = 0;
  long iterations = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    scenario->beforeStep(sim, sim.state().time);
    const StepStats s = sim.step();
    assembly += s.assemblySeconds;
    setup += s.setupSeconds;
    solve += s.solveSeconds;
    iterations += s.iterations;
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%-22s %8lld  %-9s %9.1f %8.1f %10.2f %9.2f %9.2f %9.2f\n", name,
              static_cast<long long>(sim.restMesh().elementCount()), toString(solver),
              steps / total, static_cast<double>(iterations) / steps, 1e3 * total / steps,
              1e3 * assembly / steps, 1e3 * setup / steps, 1e3 * solve / steps);
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 30;
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const Dataset sample = loadDataset(data + "bunny.json");
  std::printf("wobble scenario, dt 1/60 s, relative residual 1e-6, %u hardware threads, %d steps\n",
              std::thread::hardware_concurrency(), steps);
  std::printf("%-22s %8s  %-9s %9s %8s %10s %9s %9s %9s\n", "mesh", "tets", "solver", "steps/s",
              "iter", "ms/step", "assembly", "setup", "solve");
  for (int level : {0, 2})
    for (SolverKind solver : {SolverKind::ConjugateGradient, SolverKind::Multigrid}) {
      const std::string name = "bunny level " + std::to_string(level);
      row(name.c_str(), sample.mesh, level, solver, steps);
    }
  // A ~100k-element dataset: the bunny at TetGen quality 1.2 on top of
  // coarser levels, built here.
  BuildOptions options;
  options.decimate = true;
  options.levels = 4;
  options.minElements = 600;
  options.maxElements = 100000;
  options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const BuildResult big = buildDataset({{"bunny.obj", readObj(data + "bunny.obj"), ""}}, options);
  for (SolverKind solver : {SolverKind::ConjugateGradient, SolverKind::Multigrid})
    row("bunny 4 levels, finest", big.dataset.mesh, 3, solver, std::max(3, steps / 5));
  (void)argv;
  return 0;
}
