// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole simulation runs: the solvers on whole runs: every solver and variant on the same
// trajectory, the initial guess, units.
#include "SimulationBodies.h"

namespace tetskin {
namespace {

using namespace test;

// The same body in other units (lengths times s, Young's modulus times s^2,
// gravity and push times s: the same motion, scaled) takes the same steps:
// the same iterations and the same trajectory, scaled. Its nodes weigh
// 1e-9 times as much: an absolute singularity threshold in the block-Jacobi
// and smoother inverses once judged such blocks singular (as those of a
// 5 cm body of soft tissue, whose CG then took 960 iterations per step, not
// 42, and the multigrid 738, not 6.5).
TEST(Simulation, TheSameBodyInOtherUnitsTakesTheSameSteps) {
  const Dataset& d = sampleDataset();
  const double s = 1e-3;
  MultiLevelTetMesh small = d.mesh;
  small.nodes *= s;
  for (SolverKind solver : {SolverKind::ConjugateGradient, SolverKind::Multigrid}) {
    Points3 ends[2];
    int iterations[2] = {0, 0};
    for (int scaled = 0; scaled < 2; ++scaled) {
      SimulationOptions options;
      options.solver = solver;
      ScenarioParameters p;
      if (scaled) {
        options.material.youngsModulus *= s * s;
        options.gravity *= s;
        p.pushAcceleration *= s;
      }
      Simulation sim(scaled ? small : d.mesh, 1, options);
      auto wobble = makeScenario("wobble", p);
      wobble->setUp(sim);
      for (int i = 0; i < 12; ++i) {
        wobble->beforeStep(sim, sim.time());
        const StepStats stats = sim.step();
        EXPECT_LE(stats.residual, options.tolerance);
        iterations[scaled] += stats.iterations;
      }
      ends[scaled] = sim.state().positions / (scaled ? s : 1.0);
    }
    std::printf("%s: %d iterations in 12 steps, %d in other units\n", toString(solver),
                iterations[0], iterations[1]);
    EXPECT_NEAR(iterations[1], iterations[0], 12) << toString(solver);
    const double diagonal = boundingBox(ends[0]).diagonal();
    EXPECT_LT((ends[1] - ends[0]).cwiseAbs().maxCoeff(), 1e-6 * diagonal) << toString(solver);
  }
}

// The solvers follow the same trajectory when each solve is tight: the
// multigrid variants differ only in their preconditioner, and the automatic
// one switches between CG and multigrid (two untimed steps and its first
// round alternate them, four steps each at the default coarse reuse of 4).
// Drop, on the
// finest level with a floor, exercises the contact springs that the
// rediscretized coarse levels take over lumped.
TEST(Simulation, CgMultigridVariantsAndAutomaticFollowTheSameTrajectory) {
  const Dataset& d = sampleDataset();
  for (const char* name : {"wobble", "drop"}) {
    std::vector<Points3> ends;
    std::vector<int> contacts;
    // 0 cg, 1 multigrid (grid levels), 2 rediscretized on the dataset's
    // levels, 3 auto, 4 multigrid (Galerkin) on the dataset's levels.
    for (int variant = 0; variant < 5; ++variant) {
      SimulationOptions options =
          scenarioOptions(name, SimulationOptions{}, extractLevel(d.mesh, d.mesh.finestLevel()));
      options.tolerance = 1e-10;
      options.solver = variant == 0   ? SolverKind::ConjugateGradient
                       : variant == 3 ? SolverKind::Automatic
                                      : SolverKind::Multigrid;
      options.coarseOperators =
          variant == 2 ? CoarseOperators::Rediscretized : CoarseOperators::Galerkin;
      if (variant == 2 || variant == 4) options.coarseLevels = CoarseLevels::Dataset;
      if (variant < 3) options.coarseReuse = variant == 2 ? 3 : 1;
      Simulation sim(d.mesh, -1, options);
      auto scenario = makeScenario(name);
      scenario->setUp(sim);
      if (std::string(name) == "drop") {  // start just above the floor: contact within 20 steps
        Points3 low = sim.restMesh().nodes;
        low.col(1).array() += *options.floorHeight + 0.02 - low.col(1).minCoeff();
        sim.setPositions(low);
      }
      int touching = 0;
      for (int i = 0; i < 20; ++i) {
        scenario->beforeStep(sim, sim.time());
        const StepStats stats = sim.step();
        EXPECT_LE(stats.residual, 1e-10) << name << " variant " << variant;
        touching = std::max(touching, stats.contacts);
      }
      // (auto: CG's samples at steps 2 and 4 at least, some of them
      // perhaps cut off and finished by multigrid.)
      if (variant == 3) {
        EXPECT_GE(sim.solverChoice()->samples(), 2) << name;
      }
      ends.push_back(sim.state().positions);
      contacts.push_back(touching);
    }
    const double size = (ends[0].colwise().maxCoeff() - ends[0].colwise().minCoeff()).norm();
    for (int variant = 1; variant < 5; ++variant)
      EXPECT_LT((ends[variant] - ends[0]).cwiseAbs().maxCoeff(), 1e-6 * size)
          << name << " variant " << variant;
    if (std::string(name) == "drop") {
      EXPECT_GT(contacts[2], 0);
    }
  }
}

// Starting each solve from the projection onto the last solutions changes
// where CG starts, not what it solves: the same trajectory at a tight
// tolerance, in far fewer iterations on a smooth motion (the wobble; CG
// counts are deterministic, so this is no timing test).
TEST(Simulation, ProjectedInitialGuessKeepsTheTrajectoryInFewerIterations) {
  const Dataset& d = sampleDataset();
  std::vector<Points3> ends;
  std::vector<long> iterations;
  for (int solutions : {0, 5}) {
    SimulationOptions options =
        scenarioOptions("wobble", SimulationOptions{}, extractLevel(d.mesh, 1));
    options.tolerance = 1e-10;
    options.guessSolutions = solutions;
    Simulation sim(d.mesh, 1, options);
    auto scenario = makeScenario("wobble");
    scenario->setUp(sim);
    long total = 0;
    for (int i = 0; i < 40; ++i) {
      scenario->beforeStep(sim, sim.time());
      const StepStats stats = sim.step();
      EXPECT_LE(stats.residual, 1e-10);
      total += stats.iterations;
    }
    ends.push_back(sim.state().positions);
    iterations.push_back(total);
  }
  const double size = (ends[0].colwise().maxCoeff() - ends[0].colwise().minCoeff()).norm();
  EXPECT_LT((ends[1] - ends[0]).cwiseAbs().maxCoeff(), 1e-7 * size);
  EXPECT_LT(iterations[1], 0.85 * static_cast<double>(iterations[0]))
      << iterations[1] << " against " << iterations[0];
}

}  // namespace
}  // namespace tetskin
