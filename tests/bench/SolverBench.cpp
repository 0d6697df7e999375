// SPDX-License-Identifier: AGPL-3.0-or-later
// The solvers over the materials a researcher simulates (issue #51): the
// bunny's 12.7k-element level and a ~109k-element dataset built here,
// wobbling at dt 1/60 s to a relative residual of 1e-6, with TetSkin's
// solvers (block-Jacobi CG, multigrid CG with its Chebyshev or Gauss-Seidel
// smoother, the automatic choice) and, on the
// same systems, a sparse direct solve (CHOLMOD, factorized every step),
// CHOLMOD's factor kept for k steps as CG's preconditioner, and hypre's
// BoomerAMG as CG's preconditioner (BaselineSolvers.h). Every cell is a
// whole run of `--steps` steps from the start (default 120: 30 coarse-rebuild
// periods of 4), repeated `--reps` times (default 3) in turn with the other
// cells; it prints each cell's median and range of ms per step over the
// repetitions, iterations per step and the step's time by stage, and with
// --json FILE writes every cell and repetition. Asserts nothing.
//
//   solver_bench [--steps N] [--reps R] [--levels small,large]
//                [--materials 0,1,2,3] [--solvers cg,multigrid,...] [--json FILE]
#include <HYPRE_utilities.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "BaselineSolvers.h"
#include "LargeBunny.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/simulation/GridHierarchy.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

using namespace tetskin;
using Clock = std::chrono::steady_clock;

namespace {

struct MaterialRow {
  std::string name, models;
  double youngsModulus, poissonRatio;
};

// The rows: today's default and what real soft bodies need.
const std::vector<MaterialRow> kMaterials = {
    {"E 2e5", "today's default (a 10 m, 18 t bunny)", 2e5, 0.3},
    {"E 2e6", "a 10-15 cm piece of tissue or gelatin", 2e6, 0.3},
    {"E 2e7", "stiffer still (a silicone toy's regime)", 2e7, 0.3},
    {"E 2e6, nu 0.45", "nearly incompressible tissue or rubber", 2e6, 0.45}};

struct Solver {
  std::string name;
  SolverKind kind = SolverKind::ConjugateGradient;
  std::function<std::unique_ptr<Preconditioner>()> preconditioner;
  CoarseLevels coarseLevels = SimulationOptions{}.coarseLevels;
  MultigridSmoother smoother = SimulationOptions{}.smoother;
};

constexpr int kCholmodKeptSteps = 10, kAmgSetupEvery = 4;

std::vector<Solver> allSolvers() {
  return {{"cg", SolverKind::ConjugateGradient, {}},
          {"multigrid", SolverKind::Multigrid, {}},
          {"auto", SolverKind::Automatic, {}},
          // The multigrid over the dataset's own coarser levels (before
          // issue #51 its only hierarchy): what the solver's grids gain.
          {"mg-dataset", SolverKind::Multigrid, {}, CoarseLevels::Dataset},
          // The multigrid with the block Gauss-Seidel smoother (before, its
          // only one) instead of Chebyshev's.
          {"mg-gauss-seidel",
           SolverKind::Multigrid,
           {},
           SimulationOptions{}.coarseLevels,
           MultigridSmoother::GaussSeidel},
          {"cholmod", SolverKind::ConjugateGradient, [] { return bench::cholmodFactor(1); }},
          {"cholmod-pcg/" + std::to_string(kCholmodKeptSteps), SolverKind::ConjugateGradient,
           [] { return bench::cholmodFactor(kCholmodKeptSteps); }},
          {"amg-pcg/" + std::to_string(kAmgSetupEvery), SolverKind::ConjugateGradient,
           [] { return bench::boomerAmg(kAmgSetupEvery); }}};
}

struct Level {
  std::string name;
  const MultiLevelTetMesh* mesh;
  int level;
};

// One run: its per-step means.
struct Run {
  double msPerStep = 0, iterations = 0, assemblyMs = 0, setupMs = 0, solveMs = 0;
  long multigridSteps = 0;
  bool failed = false;
  std::string error;
};

Run run(const Level& level, const MaterialRow& material, const Solver& solver, int steps) {
  SimulationOptions options;
  options.material.youngsModulus = material.youngsModulus;
  options.material.poissonRatio = material.poissonRatio;
  options.solver = solver.kind;
  options.preconditioner = solver.preconditioner;
  options.coarseLevels = solver.coarseLevels;
  options.smoother = solver.smoother;
  options.tolerance = 1e-6;
  Run r;
  try {
    Simulation sim(*level.mesh, level.level, options);
    const std::unique_ptr<Scenario> wobble = makeScenario("wobble");
    wobble->setUp(sim);
    double seconds = 0;
    for (int i = 0; i < steps; ++i) {
      const Clock::time_point start = Clock::now();
      wobble->beforeStep(sim, sim.time());
      const StepStats s = sim.step();
      seconds += std::chrono::duration<double>(Clock::now() - start).count();
      r.iterations += s.iterations;
      r.assemblyMs += 1e3 * s.assemblySeconds;
      r.setupMs += 1e3 * s.setupSeconds;
      r.solveMs += 1e3 * s.solveSeconds;
      r.multigridSteps += s.solver == SolverKind::Multigrid;
    }
    r.msPerStep = 1e3 * seconds / steps;
    r.iterations /= steps;
    r.assemblyMs /= steps;
    r.setupMs /= steps;
    r.solveMs /= steps;
  } catch (const std::exception& e) {
    r.failed = true;
    r.error = e.what();
  }
  return r;
}

// (h^2 + h beta) E / (rho L^2), L the body's largest extent: how stiff the
// body is for its time step (the difficulty number).
double difficulty(const MaterialRow& m, const TetMesh& rest) {
  const double h = 1.0 / 60, beta = ElasticMaterial{}.stiffnessDamping;
  const double length = boundingBox(rest.nodes).extent().maxCoeff();
  return (h * h + h * beta) * m.youngsModulus / (ElasticMaterial{}.density * length * length);
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  bench::startMpi(argc, argv);
  HYPRE_Init();
  int steps = 120, reps = 3;
  std::vector<std::string> levelNames = {"small", "large"}, solverNames;
  std::vector<int> materialRows = {0, 1, 2, 3};
  std::string jsonPath;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string option = argv[i], value = argv[i + 1];
    if (option == "--steps")
      steps = std::stoi(value);
    else if (option == "--reps")
      reps = std::stoi(value);
    else if (option == "--levels")
      levelNames = split(value);
    else if (option == "--solvers")
      solverNames = split(value);
    else if (option == "--json")
      jsonPath = value;
    else if (option == "--materials") {
      materialRows.clear();
      for (const std::string& row : split(value)) materialRows.push_back(std::stoi(row));
    } else {
      std::fprintf(stderr, "unknown option %s\n", option.c_str());
      return 2;
    }
  }
  std::vector<Solver> solvers;
  for (const Solver& s : allSolvers())
    if (solverNames.empty() ||
        std::find(solverNames.begin(), solverNames.end(), s.name) != solverNames.end())
      solvers.push_back(s);

  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const Dataset sample = loadDataset(data + "bunny.json");
  std::vector<Level> levels;
  BuildResult big;
  for (const std::string& name : levelNames) {
    if (name == "small") levels.push_back({"bunny level 2", &sample.mesh, 2});
    if (name == "large") {
      big = bench::buildLargeBunny(data);
      levels.push_back({"bunny, 4 levels, finest", &big.dataset.mesh, 3});
    }
  }

  std::printf(
      "wobble, dt 1/60 s, relative residual 1e-6, %d steps per run from the start, %d runs per "
      "cell in turn, %u hardware threads\n",
      steps, reps, std::thread::hardware_concurrency());
  // results[level][material][solver] = the runs
  std::map<std::string, std::map<std::string, std::map<std::string, std::vector<Run>>>> results;
  for (int rep = 0; rep < reps; ++rep)
    for (const Level& level : levels)
      for (int m : materialRows)
        for (const Solver& solver : solvers) {
          const Run r = run(level, kMaterials[static_cast<std::size_t>(m)], solver, steps);
          results[level.name][kMaterials[static_cast<std::size_t>(m)].name][solver.name].push_back(
              r);
          std::fprintf(stderr, "  run %d: %s, %s, %s: %.1f ms/step, %.1f iterations%s\n", rep + 1,
                       level.name.c_str(), kMaterials[static_cast<std::size_t>(m)].name.c_str(),
                       solver.name.c_str(), r.msPerStep, r.iterations,
                       r.failed ? (" FAILED: " + r.error).c_str() : "");
        }

  nlohmann::json json;
  json["steps"] = steps;
  json["repetitions"] = reps;
  json["threads"] = std::thread::hardware_concurrency();
  json["tolerance"] = 1e-6;
  for (const Level& level : levels) {
    const TetMesh rest = extractLevel(*level.mesh, level.level);
    std::printf("\n%s: %lld elements, %lld nodes\n", level.name.c_str(),
                static_cast<long long>(rest.elementCount()),
                static_cast<long long>(rest.nodeCount()));
    // The multigrid's hierarchies: its own grids and the dataset's levels.
    std::string grids = std::to_string(rest.nodeCount()), datasetLevels = grids;
    for (const GridLevel& grid : enclosingGrids(rest).levels)
      grids += " / " + std::to_string(grid.nodes.rows());
    for (int coarser = level.level - 1; coarser >= 0; --coarser)
      datasetLevels +=
          " / " + std::to_string(level.mesh->levels[static_cast<std::size_t>(coarser)].nodeCount);
    std::printf("multigrid nodes per level: grid %s; dataset %s\n", grids.c_str(),
                datasetLevels.c_str());
    std::printf("%-16s %-18s %10s %17s %8s %9s %8s %8s %8s %7s\n", "material", "solver", "ms/step",
                "(range)", "vs cg", "iter", "element", "setup", "solve", "steps/s");
    nlohmann::json& levelJson = json["levels"][level.name];
    levelJson["elements"] = rest.elementCount();
    levelJson["nodes"] = rest.nodeCount();
    levelJson["grid_levels"] = grids;
    levelJson["dataset_levels"] = datasetLevels;
    for (int m : materialRows) {
      const MaterialRow& material = kMaterials[static_cast<std::size_t>(m)];
      const double L = difficulty(material, rest);
      std::printf("%s: %s, difficulty %.2g\n", material.name.c_str(), material.models.c_str(), L);
      nlohmann::json& materialJson = levelJson["materials"][material.name];
      materialJson["models"] = material.models;
      materialJson["youngs_modulus"] = material.youngsModulus;
      materialJson["poisson_ratio"] = material.poissonRatio;
      materialJson["difficulty"] = L;
      std::vector<double> cgTimes;
      for (const Run& r : results[level.name][material.name]["cg"]) cgTimes.push_back(r.msPerStep);
      const double cg = cgTimes.empty() ? 0 : median(cgTimes);
      for (const Solver& solver : solvers) {
        const std::vector<Run>& runs = results[level.name][material.name][solver.name];
        std::vector<double> ms, iterations, assembly, setup, solve;
        bool failed = false;
        nlohmann::json runsJson = nlohmann::json::array();
        for (const Run& r : runs) {
          failed = failed || r.failed;
          ms.push_back(r.msPerStep);
          iterations.push_back(r.iterations);
          assembly.push_back(r.assemblyMs);
          setup.push_back(r.setupMs);
          solve.push_back(r.solveMs);
          runsJson.push_back({{"ms_per_step", r.msPerStep},
                              {"iterations", r.iterations},
                              {"element_pass_ms", r.assemblyMs},
                              {"setup_ms", r.setupMs},
                              {"solve_ms", r.solveMs},
                              {"multigrid_steps", r.multigridSteps},
                              {"error", r.error}});
        }
        nlohmann::json& cell = materialJson["solvers"][solver.name];
        cell["runs"] = runsJson;
        if (failed) {
          std::printf("  %-14s %-18s failed: %s\n", "", solver.name.c_str(),
                      runs.front().error.c_str());
          cell["failed"] = true;
          continue;
        }
        const double t = median(ms);
        cell["ms_per_step"] = t;
        cell["ms_per_step_range"] = {*std::min_element(ms.begin(), ms.end()),
                                     *std::max_element(ms.begin(), ms.end())};
        cell["iterations"] = median(iterations);
        cell["vs_cg"] = cg > 0 ? cg / t : 0;
        char range[40];
        std::snprintf(range, sizeof range, "%.1f-%.1f", *std::min_element(ms.begin(), ms.end()),
                      *std::max_element(ms.begin(), ms.end()));
        std::printf("  %-14s %-18s %10.1f %17s %7.2fx %9.1f %8.1f %8.1f %8.1f %7.1f\n", "",
                    solver.name.c_str(), t, range, cg > 0 ? cg / t : 0.0, median(iterations),
                    median(assembly), median(setup), median(solve), 1e3 / t);
      }
    }
  }
  if (!jsonPath.empty()) {
    std::ofstream(jsonPath) << json.dump(2) << "\n";
    std::printf("\nwrote %s\n", jsonPath.c_str());
  }
  HYPRE_Finalize();
  bench::finishMpi();
  return 0;
}
