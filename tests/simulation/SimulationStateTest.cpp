// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole simulation runs: the simulation's state and its errors: time and steps, setters, external
// forces, a blown-up step, the iteration limit, inverted elements, bad options, the level's
// numbering, reading while stepping.
#include "SimulationBodies.h"

namespace tetskin {
namespace {

using namespace test;

// time() and steps() are the state's, without its rows.
TEST(Simulation, TimeAndStepsAreTheStates) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 0, SimulationOptions{});
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(sim.time(), sim.state().time);
    EXPECT_EQ(sim.steps(), sim.state().steps);
    EXPECT_EQ(sim.steps(), i);
    sim.step();
  }
  EXPECT_DOUBLE_EQ(sim.time(), 3 * sim.options().timeStep);
}

// A step that blows up is an error naming the step and, where a node went
// beyond 1e30 (here under a load of 1e40 N), a node of the level; the state
// stays the last good one. Positions that far out would make frames no
// reader takes (they refuse coordinates beyond 1e30), and NaN would
// follow; a load of 1e300 N overflows the solve itself. Two separate
// tetrahedra, the second loaded: only its nodes (4..7) blow up.
TEST(Simulation, ABlownUpStepIsAnErrorAndKeepsTheLastState) {
  const TetMesh one = test::unitTetrahedron();
  TetMesh two;
  two.nodes.resize(8, 3);
  two.nodes << one.nodes, one.nodes.rowwise() + Eigen::RowVector3d(5, 0, 0);
  two.elements.resize(2, 4);
  two.elements << one.elements, one.elements.array() + 4;
  SimulationOptions options;
  options.solver = SolverKind::ConjugateGradient;
  Simulation sim(oneLevel(two), 0, options);
  sim.step();
  const SimulationState before = sim.state();
  auto stepUnder = [&](double load) {
    Points3 loads = Points3::Zero(8, 3);
    loads(6, 0) = load;
    sim.setExternalForces(loads);
    return test::errorText([&] { sim.step(); });
  };
  const std::string prefix = "the simulation diverged in step 2 \\(t = 0\\.0333333 s\\): ";
  const std::string advice =
      "; smaller loads or time steps, or a stiffer material, may keep it stable";
  std::string message = stepUnder(1e40);
  std::smatch node;
  EXPECT_TRUE(std::regex_match(message, node,
                               std::regex(prefix +
                                          "node ([0-9]+) would get a (position|velocity) "
                                          "component of [0-9.e+]+ m(/s)?, beyond 1e\\+30 m(/s)?" +
                                          advice)))
      << message;
  if (!node.empty()) {
    EXPECT_GE(std::stoi(node[1]), 4) << message;
  }
  message = stepUnder(1e300);
  EXPECT_TRUE(std::regex_match(
      message, std::regex(prefix + "the solver's velocity update is not finite" + advice)))
      << message;
  const SimulationState after = sim.state();
  EXPECT_EQ(after.steps, 1);
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(after.positions, before.positions);
  EXPECT_EQ(after.velocities, before.velocities);
  // Without the load it goes on.
  EXPECT_EQ(stepUnder(0), "no error");
  EXPECT_EQ(sim.steps(), 2);
  EXPECT_TRUE(sim.state().positions.allFinite());
}

// Solves cut off at the iteration limit above the tolerance are counted,
// with the largest residual and its step; solves that converge are not.
TEST(Simulation, SolvesStoppedAtTheIterationLimitAreCounted) {
  const Dataset& d = sampleDataset();
  SimulationOptions options;
  Simulation converging(d.mesh, 0, options);
  for (int i = 0; i < 3; ++i) converging.step();
  EXPECT_EQ(converging.solveShortfall().steps, 0);
  options.maxIterations = 2;
  Simulation cut(d.mesh, 0, options);
  double largest = 0;
  Index largestAt = 0;
  for (int i = 0; i < 3; ++i) {
    const StepStats stats = cut.step();
    EXPECT_EQ(stats.iterations, 2);
    EXPECT_GT(stats.residual, options.tolerance);
    if (stats.residual > largest) {
      largest = stats.residual;
      largestAt = i + 1;
    }
  }
  const SolveShortfall shortfall = cut.solveShortfall();
  EXPECT_EQ(shortfall.steps, 3);
  EXPECT_EQ(shortfall.largestResidual, largest);
  EXPECT_EQ(shortfall.largestAtStep, largestAt);
  const std::string described =
      "3 steps stopped at the iteration limit (2) with the relative residual above the "
      "tolerance 1e-06 (at most " +
      formatNumber(largest) + ", in step " + std::to_string(largestAt) + ")";
  EXPECT_EQ(describe(shortfall, options, "MG"),
            described + "; MG needs far fewer iterations on stiff bodies");
  options.solver = SolverKind::Multigrid;  // (already the multigrid: no advice)
  EXPECT_EQ(describe(shortfall, options, "MG"), described);
}

// A state set from outside (the GUI's pull, a restart) has one row per
// node of the simulated level; any other count is refused with both counts.
TEST(Simulation, StateSettersRefuseAnotherNumberOfRows) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 0, SimulationOptions{});
  const Index n = sim.restMesh().nodeCount();
  const Points3 wrong = Points3::Zero(n + 1, 3);
  const std::string counts =
      ": " + std::to_string(n + 1) + " rows for " + std::to_string(n) + " nodes";
  EXPECT_EQ(test::errorText([&] { sim.setExternalForces(wrong); }), "external forces" + counts);
  EXPECT_EQ(test::errorText([&] { sim.setPositions(wrong); }), "positions" + counts);
  EXPECT_EQ(test::errorText([&] { sim.setVelocities(wrong); }), "velocities" + counts);
  EXPECT_EQ(sim.state().positions, sim.restMesh().nodes);  // nothing was set
}

// A non-finite force (a NaN from a script, an overflowing load) is refused
// where it is set, naming its node, and the forces before it stay.
TEST(Simulation, ExternalForcesRefuseANonFiniteForceNamingItsNode) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 0, SimulationOptions{});
  Points3 forces = Points3::Zero(sim.restMesh().nodeCount(), 3);
  forces(7, 0) = 2;
  sim.setExternalForces(forces);
  Points3 bad = forces;
  bad(12, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(test::errorText([&] { sim.setExternalForces(bad); }),
            "external forces: node 12's force is not finite");
  bad(12, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(sim.setExternalForces(bad), Error);
  EXPECT_EQ(sim.externalForces(), forces);
}

// The state reports the external forces of the step that led to it (what
// the exported frames show as ExternalForce): none before the first step,
// and forces set for the next step only once it is taken.
TEST(Simulation, StateHoldsTheExternalForcesOfTheLastStep) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 0, SimulationOptions{});
  const Index n = sim.restMesh().nodeCount();
  EXPECT_EQ(sim.state().externalForces, Points3::Zero(n, 3));
  Points3 first = Points3::Zero(n, 3), second = Points3::Zero(n, 3);
  first.row(7) << 1, -2, 3;
  second.row(9) << 0, 5, 0;
  sim.setExternalForces(first);
  EXPECT_EQ(sim.state().externalForces, Points3::Zero(n, 3));  // not taken yet
  sim.step();
  EXPECT_EQ(sim.state().externalForces, first);
  sim.setExternalForces(second);
  EXPECT_EQ(sim.state().externalForces, first);
  sim.step();
  EXPECT_EQ(sim.state().externalForces, second);
}

// Inside, nodes are renumbered breadth first; everything the caller sees
// uses the level's own numbering.
TEST(Simulation, CallersSeeTheLevelsNodeNumbering) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 1, SimulationOptions{});
  const TetMesh& rest = sim.restMesh();
  const TetMesh level = extractLevel(d.mesh, 1);
  EXPECT_EQ(rest.nodes, level.nodes);
  EXPECT_EQ(rest.elements, level.elements);
  const CorotatedFem reference(level, SimulationOptions{}.material);
  for (Index v = 0; v < rest.nodeCount(); ++v)
    EXPECT_DOUBLE_EQ(sim.nodeMasses()[v], reference.lumpedMass()[3 * v]);
  EXPECT_EQ(sim.state().positions, rest.nodes);
  Points3 moved = rest.nodes;
  moved.row(7) += Eigen::RowVector3d(0.1, 0.2, 0.3);
  sim.setPositions(moved);
  EXPECT_EQ(sim.state().positions, moved);
  Points3 forces = Points3::Zero(rest.nodeCount(), 3);
  forces(11, 2) = 5;
  sim.setExternalForces(forces);
  EXPECT_EQ(sim.externalForces(), forces);
  // Node 7 (level numbering) held in place, the others fall.
  sim.setPositions(rest.nodes);
  sim.setFixedNodes({7});
  sim.step();
  const Points3 after = sim.state().positions;
  EXPECT_EQ(after.row(7), rest.nodes.row(7));
  EXPECT_LT(after(0, 1), rest.nodes(0, 1));
}

TEST(Simulation, StateCanBeReadWhileAnotherThreadSteps) {
  const Dataset& d = sampleDataset();
  Simulation sim(d.mesh, 0, SimulationOptions{});
  makeScenario("sag")->setUp(sim);
  std::atomic<bool> done{false};
  std::thread stepper([&] {
    for (int i = 0; i < 30; ++i) sim.step();
    done = true;
  });
  Index reads = 0;
  while (!done) {
    const SimulationState s = sim.state();
    ASSERT_TRUE(s.positions.allFinite());
    ASSERT_EQ(s.positions.rows(), sim.restMesh().nodeCount());
    sim.setExternalForces(Points3::Zero(sim.restMesh().nodeCount(), 3));
    ++reads;
  }
  stepper.join();
  EXPECT_EQ(sim.steps(), 30);
  EXPECT_GT(reads, 0);
}

TEST(Simulation, BadParametersAreErrors) {
  const TetMesh block = test::tetGrid(1, 1, 1, {1, 1, 1});
  SimulationOptions options;
  options.material.poissonRatio = 0.5;
  EXPECT_THROW(Simulation(oneLevel(block), 0, options), Error);
  options = {};
  options.timeStep = 0;
  EXPECT_THROW(Simulation(oneLevel(block), 0, options), Error);
  options = {};
  options.guessSolutions = -1;
  EXPECT_THROW(Simulation(oneLevel(block), 0, options), Error);
  EXPECT_THROW(makeScenario("spin"), Error);
}

// Each option out of its range, NaN and infinity included, is an error
// that names it, and a valid set is not.
TEST(Simulation, OptionsOutOfRangeAreErrorsNamingTheOption) {
  const TetMesh block = test::tetGrid(1, 1, 1, {1, 1, 1});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::function<void(SimulationOptions&)>, std::string>> cases = {
      {[&](auto& o) { o.timeStep = nan; }, "time step"},
      {[&](auto& o) { o.timeStep = inf; }, "time step"},
      {[&](auto& o) { o.timeStep = -0.01; }, "time step"},
      {[&](auto& o) { o.tolerance = nan; }, "tolerance"},
      {[&](auto& o) { o.tolerance = 0; }, "tolerance"},
      {[&](auto& o) { o.tolerance = 1; }, "tolerance"},
      {[&](auto& o) { o.maxIterations = 0; }, "iteration"},
      {[&](auto& o) { o.coarseReuse = 0; }, "coarse-operator reuse"},
      {[&](auto& o) { o.friction = -0.5; }, "friction"},
      {[&](auto& o) { o.friction = nan; }, "friction"},
      {[&](auto& o) { o.floorStiffness = -1; }, "floor stiffness"},
      {[&](auto& o) { o.floorHeight = nan; }, "floor height"},
      {[&](auto& o) { o.gravity.y() = nan; }, "gravity"},
      {[&](auto& o) { o.material.youngsModulus = inf; }, "Young's modulus"},
      {[&](auto& o) { o.material.massDamping = inf; },
       "Rayleigh mass damping (alpha) must be finite and >= 0, got inf"},
      {[&](auto& o) { o.material.stiffnessDamping = -0.5; },
       "Rayleigh stiffness damping (beta) must be finite and >= 0, got -0.5"},
      {[&](auto& o) { o.material.density = 0; }, "density must be finite and positive, got 0"},
      {[&](auto& o) { o.material.poissonRatio = 0.5; },
       "Poisson's ratio must lie in (-1, 0.5), got 0.5"},
      {[&](auto& o) { o.material.poissonRatio = -1; },
       "Poisson's ratio must lie in (-1, 0.5), got -1"},
  };
  EXPECT_NO_THROW(Simulation(oneLevel(block), 0, SimulationOptions{}));
  for (const auto& [spoil, name] : cases) {
    SimulationOptions options;
    spoil(options);
    try {
      Simulation(oneLevel(block), 0, options);
      ADD_FAILURE() << "no error for a bad " << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

// A level with an inverted element is refused, naming the dataset, the
// level and the element; a coarse level only where the multigrid uses it
// (on the dataset's levels: the solver's own grid levels do not read them).
TEST(Simulation, InvertedElementIsAnErrorNamingDatasetLevelAndElement) {
  MultiLevelTetMesh dataset;
  TetMesh coarse = test::tetGrid(1, 1, 1, {1, 1, 1});
  std::swap(coarse.elements(2, 0), coarse.elements(2, 1));  // element 2 turned inside out
  appendLevel(dataset, coarse);
  appendLevel(dataset, test::tetGrid(2, 2, 2, {1, 1, 1}));
  auto message = [&](int level, SolverKind solver, CoarseLevels levels) -> std::string {
    SimulationOptions options;
    options.solver = solver;
    options.coarseLevels = levels;
    try {
      Simulation(dataset, level, options, "blocks.json");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  for (CoarseLevels levels : {CoarseLevels::Grid, CoarseLevels::Dataset})
    EXPECT_EQ(message(1, SolverKind::ConjugateGradient, levels), "");
  for (SolverKind solver : {SolverKind::Multigrid, SolverKind::Automatic}) {
    EXPECT_EQ(message(1, solver, CoarseLevels::Grid), "");
    EXPECT_EQ(message(1, solver, CoarseLevels::Dataset)
                  .rfind("blocks.json: level 0 (a coarser level, used by the "
                         "multigrid solver): element 2 has non-positive volume -",
                         0),
              0u)
        << message(1, solver, CoarseLevels::Dataset);
  }
  EXPECT_EQ(message(0, SolverKind::ConjugateGradient, CoarseLevels::Grid)
                .rfind("blocks.json: level 0: element 2 has non-positive volume -", 0),
            0u)
      << message(0, SolverKind::ConjugateGradient, CoarseLevels::Grid);
}

TEST(Simulation, InvertedElementsRecoverWithoutNaN) {
  const TetMesh block = test::tetGrid(3, 3, 3, {1, 1, 1});
  SimulationOptions options;
  options.material.youngsModulus = 1e4;
  options.material.density = 10;
  options.material.massDamping = 5;  // settle within the test's 300 steps
  options.gravity.setZero();
  Simulation sim(oneLevel(block), 0, options);
  Points3 flipped = block.nodes;
  flipped.col(1) *= -0.2;  // mirror and flatten: every element inverted
  sim.setPositions(flipped);
  const double initial = sim.energies().elastic;
  for (int i = 0; i < 300; ++i) sim.step();
  const Points3 x = sim.state().positions;
  ASSERT_TRUE(x.allFinite());
  TetMesh now = block;
  now.nodes = x;
  Index positive = 0;
  for (Index e = 0; e < now.elementCount(); ++e) positive += elementVolume(now, e) > 0 ? 1 : 0;
  EXPECT_EQ(positive, now.elementCount());
  // Back to its rest shape up to a rigid motion: no elastic energy left.
  EXPECT_LT(sim.energies().elastic, 1e-9 * initial);
  EXPECT_NEAR(meshVolume(now), 1.0, 1e-6);
}

}  // namespace
}  // namespace tetskin
