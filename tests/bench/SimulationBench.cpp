// SPDX-License-Identifier: AGPL-3.0-or-later
// Implicit steps per second of the wobble scenario with block-Jacobi CG and
// with multigrid-preconditioned CG, both to the same relative residual, in the
// same run. Prints a table; asserts nothing.
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "LargeBunny.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/simulation/LinearSolvers.h"
#include "tetskin/simulation/NodeBlockMatrix.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

using namespace tetskin;

namespace {

// The wobble scenario set up on a simulation of `level`.
struct Wobble {
  std::unique_ptr<Simulation> sim;
  std::unique_ptr<Scenario> scenario;
  StepStats step() {
    scenario->beforeStep(*sim, sim->time());
    return sim->step();
  }
};

// A solver configuration as the table names it.
struct Solver {
  SolverKind kind = SolverKind::ConjugateGradient;
  CoarseOperators coarse = CoarseOperators::Rediscretized;
  int coarseReuse = 1;
  bool singlePrecisionCycle = true;
  int guessSolutions = SimulationOptions{}.guessSolutions;
  Tangent tangent = Tangent::Full;
  std::string name() const {
    const char* base = kind == SolverKind::ConjugateGradient ? "cg"
                       : coarse == CoarseOperators::Galerkin ? "mg-galerkin"
                                                             : "mg";
    char text[48];  // (snprintf: GCC's -Wrestrict misfires on string concatenation)
    char reuse[16] = "";
    if (coarseReuse > 1) std::snprintf(reuse, sizeof reuse, "/%d", coarseReuse);
    std::snprintf(text, sizeof text, "%s%s%s%s%s", base, reuse,
                  singlePrecisionCycle ? "" : " double", guessSolutions == 0 ? " plain" : "",
                  tangent == Tangent::Warped ? " warped" : "");
    return text;
  }
};

Wobble wobble(const MultiLevelTetMesh& mesh, int level, const Solver& solver, double tolerance,
              double youngsModulus = ElasticMaterial{}.youngsModulus) {
  SimulationOptions options;
  options.material.youngsModulus = youngsModulus;
  options.solver = solver.kind;
  options.coarseOperators = solver.coarse;
  // (The rows of this table are the dataset's levels' multigrid; solver_bench
  // times the solver's own grid levels.)
  options.coarseLevels = CoarseLevels::Dataset;
  options.coarseReuse = solver.coarseReuse;
  options.singlePrecisionCycle = solver.singlePrecisionCycle;
  options.guessSolutions = solver.guessSolutions;
  options.tangent = solver.tangent;
  options.tolerance = tolerance;
  Wobble run{std::make_unique<Simulation>(mesh, level, options), makeScenario("wobble")};
  run.scenario->setUp(*run.sim);
  return run;
}

void row(const char* name, const MultiLevelTetMesh& mesh, int level, const Solver& solver,
         int steps, double youngsModulus = ElasticMaterial{}.youngsModulus) {
  Wobble run = wobble(mesh, level, solver, 1e-6, youngsModulus);
  const Simulation& sim = *run.sim;
  // Warm up: one-time setup (e.g. Galerkin streams) and the first steps, in
  // which the initial guess has fewer solutions to combine, are not timed.
  for (int i = 0; i < std::max(2, solver.guessSolutions); ++i) run.step();
  double assembly = 0, setup = 0, solve = 0;
  long iterations = 0;
  std::vector<double> seconds;  // per step: the median shrugs off the VM's pauses
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    const auto stepStart = std::chrono::steady_clock::now();
    const StepStats s = run.step();
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
    assembly += s.assemblySeconds;
    setup += s.setupSeconds;
    solve += s.solveSeconds;
    iterations += s.iterations;
  }
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::nth_element(seconds.begin(), seconds.begin() + steps / 2, seconds.end());
  std::printf("%-22s %8lld  %-20s %9.1f %9.1f %8.1f %10.2f %9.2f %9.2f %9.2f\n", name,
              static_cast<long long>(sim.restMesh().elementCount()), solver.name().c_str(),
              steps / total, 1.0 / seconds[static_cast<std::size_t>(steps / 2)],
              static_cast<double>(iterations) / steps, 1e3 * total / steps, 1e3 * assembly / steps,
              1e3 * setup / steps, 1e3 * solve / steps);
}

// How far a looser solve tolerance moves the trajectory: the wobble run with
// each tolerance against the same run at 1e-8, over `steps` steps; prints the
// largest node distance (relative to the bounding-box diagonal) and the mean
// iterations.
void toleranceAccuracy(const MultiLevelTetMesh& mesh, int level, const Solver& solver, int steps) {
  auto run = [&](double tolerance, double& iterations, double& seconds) {
    Wobble wobbling = wobble(mesh, level, solver, tolerance);
    long total = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) total += wobbling.step().iterations;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    iterations = static_cast<double>(total) / steps;
    return wobbling.sim->state().positions;
  };
  double iterations = 0, seconds = 0;
  const Points3 reference = run(1e-8, iterations, seconds);
  const double diagonal = (reference.colwise().maxCoeff() - reference.colwise().minCoeff()).norm();
  for (double tolerance : {1e-6, 1e-4, 1e-3, 1e-2}) {
    const Points3 positions = run(tolerance, iterations, seconds);
    std::printf(
        "  %-14s tolerance %-6g  %5.1f iter  %7.1f steps/s  largest deviation %.2e of the "
        "diagonal\n",
        solver.name().c_str(), tolerance, iterations, steps / seconds,
        (positions - reference).rowwise().norm().maxCoeff() / diagonal);
  }
}

// Rotation extraction per element and step: the SVD (the reference) against
// the warm-started quaternion ascent the stepper uses, on deformation
// gradients that drift a little from call to call, as between time steps.
void rotations() {
  constexpr int kCount = 200000;
  std::vector<Eigen::Matrix3d> gradients(kCount);
  for (int i = 0; i < kCount; ++i)
    gradients[static_cast<std::size_t>(i)] =
        Eigen::AngleAxisd(1e-3 * i, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
        (Eigen::Matrix3d::Identity() + 0.05 * Eigen::Matrix3d::Random());
  double checksum = 0;
  auto time = [&](auto&& extract) {
    const auto start = std::chrono::steady_clock::now();
    for (const Eigen::Matrix3d& F : gradients) checksum += extract(F)(0, 0);
    return 1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           kCount;
  };
  const double svd = time([](const Eigen::Matrix3d& F) { return CorotatedFem::rotation(F); });
  Eigen::Quaterniond warm = Eigen::Quaterniond::Identity();
  const double fast =
      time([&warm](const Eigen::Matrix3d& F) { return CorotatedFem::rotation(F, warm); });
  std::printf(
      "rotation extraction, 1 thread: SVD %.0f ns, warm-started quaternion %.0f ns (%.1fx)"
      " [checksum %.3g]\n",
      svd, fast, svd / fast, checksum);
}

// The element pass (rotations, forces and the implicit step's matrix) on
// `level`, with the vector kernel this CPU runs fastest against the baseline
// kernel, and with the full tangent (the default) against R K R^T alone,
// alternating; the state drifts a little from call to call, as between time
// steps, so the rotations take their usual Newton steps.
void elementPasses(const MultiLevelTetMesh& mesh, int level) {
  const TetMesh rest = extractLevel(mesh, level);
  CorotatedFem fastest(rest, ElasticMaterial{}), baseline(rest, ElasticMaterial{});
  baseline.setKernel(SimdKernel::Baseline);
  const Eigen::VectorXd drift = 1e-4 * Eigen::VectorXd::Random(fastest.dofCount());
  Eigen::VectorXd x = fastest.restPositions() + 1e-2 * Eigen::VectorXd::Random(fastest.dofCount());
  Eigen::VectorXd force, diagonal = fastest.lumpedMass(),
                         velocity = Eigen::VectorXd::Random(fastest.dofCount());
  SparseMatrix A = fastest.pattern();
  CorotatedFem::SystemTerms full;  // the step's terms at h = 1/60 s, beta = 0
  full.stiffnessScale = 1.0 / 3600;
  full.diagonal = &diagonal;
  full.velocity = &velocity;
  full.velocityWeight = 1.0 / 60;
  full.rotationScale = 1.0 / 3600;
  full.rotationVelocityWeight = 1.0 / 60;
  CorotatedFem::SystemTerms warped = full;
  warped.rotationScale = warped.rotationVelocityWeight = 0;
  constexpr int kRepeats = 50;
  auto time = [&](CorotatedFem& fem, const CorotatedFem::SystemTerms& terms) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kRepeats; ++i) {
      x += (i % 2 ? -1.0 : 1.0) * drift;
      fem.update(x, force, A, terms);
    }
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           kRepeats;
  };
  std::vector<double> vector, scalar, vectorWarped;
  for (int round = 0; round < 5; ++round) {
    vector.push_back(time(fastest, full));
    scalar.push_back(time(baseline, full));
    vectorWarped.push_back(time(fastest, warped));
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + 2, v.end());
    return v[2];
  };
  const double fast = median(vector), slow = median(scalar), warp = median(vectorWarped);
  std::printf(
      "element pass, bunny level %d (%lld elements), median of 5 x %d: %s kernel %.2f ms, "
      "baseline kernel %.2f ms (%.2fx); warped tangent (no rotation term) %.2f ms (full costs "
      "%.2fx)\n",
      level, static_cast<long long>(fastest.elementCount()), kRepeats,
      usesAvx2Kernels() ? "AVX2" : "baseline", fast, slow, slow / fast, warp, fast / warp);
}

// CG's product on one system of `level` (rest shape perturbed, the implicit
// step's terms): the row-major SparseMatrix kernel against the block copy
// CG multiplies with, and the copy itself (once per step), alternating.
void products(const MultiLevelTetMesh& mesh, int level) {
  CorotatedFem fem(extractLevel(mesh, level), ElasticMaterial{});
  const Eigen::VectorXd x = fem.restPositions() + 1e-3 * Eigen::VectorXd::Random(fem.dofCount());
  Eigen::VectorXd force, diagonal = fem.lumpedMass();
  SparseMatrix A = fem.pattern();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 1.0 / 3600;
  terms.diagonal = &diagonal;
  fem.update(x, force, A, terms);
  NodeBlockMatrix blocks(A);
  const FloatNodeBlockMatrix floatBlocks(A);
  const Eigen::VectorXd in = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXf floatIn = in.cast<float>();
  Eigen::VectorXd out(A.rows());
  Eigen::VectorXf floatOut(A.rows());
  constexpr int kRepeats = 1000;
  auto time = [&](auto&& work) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kRepeats; ++i) work();
    return 1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           kRepeats;
  };
  std::vector<double> sparse, block, baseline, single, copy;
  for (int round = 0; round < 5; ++round) {
    sparse.push_back(time([&] { multiply(A, in, out); }));
    block.push_back(time([&] { multiply(blocks, in, out); }));
    baseline.push_back(time([&] { multiply(blocks, in, out, SimdKernel::Baseline); }));
    single.push_back(time([&] { multiply(floatBlocks, floatIn, floatOut); }));
    copy.push_back(time([&] { blocks.assign(A); }));
  }
  auto median = [](std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + 2, values.end());
    return values[2];
  };
  std::printf(
      "CG product, bunny level %d (%lld dofs, %lld entries), median of 5 x %d: "
      "SparseMatrix %.1f us; NodeBlockMatrix %.1f us (%.2fx, %s kernel), baseline kernel "
      "%.1f us (%.2fx); float blocks (V-cycle) %.1f us (%.2fx); block copy %.1f us\n",
      level, static_cast<long long>(A.rows()), static_cast<long long>(A.nonZeros()), kRepeats,
      median(sparse), median(block), median(sparse) / median(block),
      usesAvx2Kernels() ? "AVX2" : "baseline", median(baseline), median(sparse) / median(baseline),
      median(single), median(sparse) / median(single), median(copy));
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 30;
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const Dataset sample = loadDataset(data + "bunny.json");
  std::printf("wobble scenario, dt 1/60 s, relative residual 1e-6, %u hardware threads, %d steps\n",
              std::thread::hardware_concurrency(), steps);
  rotations();
  elementPasses(sample.mesh, 2);
  products(sample.mesh, 2);
  std::printf(
      "(mg: rediscretized coarse operators, mg-galerkin: Galerkin products; /N: coarse "
      "operators rebuilt every N steps; V-cycles in single precision unless 'double'; each "
      "solve starts from the projection onto the last %d solutions, 'plain': from the last "
      "solution as it is; the full tangent unless 'warped': R K R^T alone)\n",
      SimulationOptions{}.guessSolutions);
  const Solver cg;
  const Solver mg{SolverKind::Multigrid, CoarseOperators::Rediscretized, 1};
  const Solver mg4{SolverKind::Multigrid, CoarseOperators::Rediscretized, 4};
  const Solver galerkin{SolverKind::Multigrid, CoarseOperators::Galerkin, 1};
  const Solver galerkin4{SolverKind::Multigrid, CoarseOperators::Galerkin, 4};
  const Solver galerkin4double{SolverKind::Multigrid, CoarseOperators::Galerkin, 4, false};
  const Solver cgPlain{SolverKind::ConjugateGradient, CoarseOperators::Rediscretized, 1, true, 0};
  const Solver galerkin4Plain{SolverKind::Multigrid, CoarseOperators::Galerkin, 4, true, 0};
  const int guess = SimulationOptions{}.guessSolutions;
  const Solver cgWarped{SolverKind::ConjugateGradient,
                        CoarseOperators::Rediscretized,
                        1,
                        true,
                        guess,
                        Tangent::Warped};
  const Solver galerkin4Warped{SolverKind::Multigrid, CoarseOperators::Galerkin, 4, true, guess,
                               Tangent::Warped};
  std::printf("wobble, bunny level 2, %d steps: trajectory against a 1e-8 solve\n", 4 * steps);
  for (const Solver& solver : {cg, cgPlain, mg, mg4, galerkin4})
    toleranceAccuracy(sample.mesh, 2, solver, 4 * steps);
  std::printf("%-22s %8s  %-20s %9s %9s %8s %10s %9s %9s %9s\n", "mesh", "tets", "solver",
              "steps/s", "(median)", "iter", "ms/step", "assembly", "setup", "solve");
  for (int level : {0, 2}) {
    const std::string name = "bunny level " + std::to_string(level);
    for (const Solver& solver : {cg, cgPlain, cgWarped, mg, mg4, galerkin, galerkin4,
                                 galerkin4Plain, galerkin4double, galerkin4Warped})
      if (level > 0 || solver.coarseReuse == 1)
        row(name.c_str(), sample.mesh, level, solver, steps);
  }
  const BuildResult big = bench::buildLargeBunny(data);
  for (const Solver& solver : {cg, cgPlain, cgWarped, mg, mg4, galerkin, galerkin4, galerkin4Plain,
                               galerkin4double, galerkin4Warped})
    row("bunny 4 levels, finest", big.dataset.mesh, 3, solver, std::max(3, steps / 5));
  // Stiffer bodies: CG's iterations grow with the square root of the
  // condition number, the multigrid's hardly.
  for (double young : {2e6, 2e7}) {
    char name[40];
    std::snprintf(name, sizeof name, "  same, E = %.0e Pa", young);
    for (const Solver& solver : {cg, mg4, galerkin4})
      row(name, big.dataset.mesh, 3, solver, std::max(3, steps / 5), young);
  }
  (void)argv;
  return 0;
}
