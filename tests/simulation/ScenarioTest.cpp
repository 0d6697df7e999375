// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole simulation runs: the scenarios: what each drives and holds, their parameters, any up axis,
// the held box.
#include "SimulationBodies.h"

namespace tetskin {
namespace {

using namespace test;

TEST(Simulation, TwistReachesItsTargetAndDropLandsOnTheFloor) {
  const Dataset& d = sampleDataset();
  {
    SimulationOptions options;
    Simulation sim(d.mesh, 0, options);
    auto twist = makeScenario("twist");
    twist->setUp(sim);
    for (int i = 0; i < 70; ++i) {
      twist->beforeStep(sim, sim.time());
      sim.step();
    }
    EXPECT_TRUE(sim.state().positions.allFinite());
    // The fixed base has not moved (its lowest node; the fixed set also
    // holds the turned top).
    Index lowest = 0;
    sim.restMesh().nodes.col(1).minCoeff(&lowest);
    const auto& fixed = sim.fixedNodes();
    ASSERT_TRUE(std::binary_search(fixed.begin(), fixed.end(), static_cast<int>(lowest)));
    const Points3 x = sim.state().positions;
    EXPECT_LT((x.row(lowest) - sim.restMesh().nodes.row(lowest)).norm(), 1e-12);
  }
  {
    SimulationOptions options =
        scenarioOptions("drop", SimulationOptions{}, extractLevel(d.mesh, 0));
    ASSERT_TRUE(options.floorHeight);
    Simulation sim(d.mesh, 0, options);
    auto drop = makeScenario("drop");
    drop->setUp(sim);
    const double start = boundingBox(sim.state().positions).min.y();
    EXPECT_GT(start, *options.floorHeight + 1);
    int contacts = 0;
    for (int i = 0; i < 240; ++i) {
      drop->beforeStep(sim, sim.time());
      contacts = std::max(contacts, sim.step().contacts);
    }
    EXPECT_GT(contacts, 0);
    const Points3 x = sim.state().positions;
    EXPECT_TRUE(x.allFinite());
    // Resting on it: held by its penalty springs, a little below the plane.
    const double diagonal = boundingBox(sim.restMesh().nodes).diagonal();
    EXPECT_GE(boundingBox(x).min.y(), *options.floorHeight - 0.005 * diagonal);
    EXPECT_LT(boundingBox(x).min.y(), *options.floorHeight + 0.05);
  }
}

// The bunny turned so that its up (y) becomes z, or x, run upright along
// that axis: every scenario (base, push, drop onto the floor, twist, the
// default gravity) runs as on the y-up bunny, turned. (Before, the
// scenarios, the floor and the gravity were y-up only: a z-up model had its
// "base" on one side and fell sideways.)
TEST(Simulation, EveryScenarioRunsOnAnyUpAxisAsOnYTurned) {
  const Dataset& d = sampleDataset();
  auto run = [&](const std::string& name, UpAxis up) {
    MultiLevelTetMesh mesh = d.mesh;
    const Eigen::Matrix3d turn = fromYUp(up);
    mesh.nodes = (mesh.nodes * turn.transpose()).eval();
    SimulationOptions options = uprightAlong(up, {});
    options.solver = SolverKind::ConjugateGradient;
    options.tolerance = 1e-10;
    options = scenarioOptions(name, options, extractLevel(mesh, 0));
    Simulation sim(mesh, 0, options);
    auto scenario = makeScenario(name);
    scenario->setUp(sim);
    int contacts = 0;
    for (int i = 0; i < 60; ++i) {  // (a second: drop lands)
      scenario->beforeStep(sim, sim.time());
      contacts += sim.step().contacts;
    }
    // Back in the y-up frame.
    return std::pair{Points3(sim.state().positions * turn), contacts};
  };
  const double diagonal = boundingBox(extractLevel(d.mesh, 0).nodes).diagonal();
  for (const char* name : {"wobble", "drop", "twist", "sag", "free"}) {
    const auto [upright, contacts] = run(name, UpAxis::Y);
    const Points3 rest = extractLevel(d.mesh, 0).nodes;
    EXPECT_GT((upright - rest).rowwise().norm().maxCoeff(), 0.01 * diagonal) << name;
    if (std::string(name) == "drop") {
      EXPECT_GT(contacts, 0);  // it landed
    }
    for (UpAxis up : {UpAxis::Z, UpAxis::X}) {
      const auto [turned, turnedContacts] = run(name, up);
      EXPECT_LT((turned - upright).rowwise().norm().maxCoeff(), 1e-6 * diagonal)
          << name << ", up " << toString(up);
      EXPECT_EQ(turnedContacts, contacts) << name << ", up " << toString(up);
    }
  }
}

// Scenario parameters: held nodes stay put in every scenario (and join the
// scenario's own fixed nodes), a base share of 0 fixes nothing (a sagging
// body then falls freely), the push scales with its acceleration, and
// values no scenario can use are refused.
TEST(Simulation, ScenarioParametersHoldNodesAndScaleThePush) {
  const Dataset& d = sampleDataset();
  const TetMesh rest = extractLevel(d.mesh, 0);
  Index top = 0, bottom = 0;
  rest.nodes.col(1).maxCoeff(&top);
  rest.nodes.col(1).minCoeff(&bottom);
  ScenarioParameters held;
  held.fixedNodes = {static_cast<int>(top)};
  for (const std::string& name : scenarioNames()) {
    Simulation sim(d.mesh, 0, scenarioOptions(name, SimulationOptions{}, rest));
    auto scenario = makeScenario(name, held);
    scenario->setUp(sim);
    const std::vector<int>& fixed = sim.fixedNodes();
    EXPECT_TRUE(std::is_sorted(fixed.begin(), fixed.end())) << name;
    EXPECT_TRUE(std::binary_search(fixed.begin(), fixed.end(), static_cast<int>(top))) << name;
    // The base (all but drop and free) is still fixed besides.
    EXPECT_EQ(std::binary_search(fixed.begin(), fixed.end(), static_cast<int>(bottom)),
              name != "drop" && name != "free")
        << name;
    const Points3 start = sim.state().positions;
    for (int i = 0; i < 10; ++i) {
      scenario->beforeStep(sim, sim.time());
      sim.step();
    }
    // Twist turns the top (its fixed nodes follow targets); elsewhere held is held.
    if (name != "twist") {
      EXPECT_LT((sim.state().positions.row(top) - start.row(top)).norm(), 1e-12) << name;
    }
  }
  {  // No base and nothing held: the whole body falls with g.
    ScenarioParameters free;
    free.baseShare = 0;
    Simulation sim(d.mesh, 0, SimulationOptions{});
    auto sag = makeScenario("sag", free);
    sag->setUp(sim);
    EXPECT_TRUE(sim.fixedNodes().empty());
    for (int i = 0; i < 6; ++i) sim.step();
    const Eigen::VectorXd m = sim.nodeMasses();
    const double fallen = m.dot(sim.state().positions.col(1) - rest.nodes.col(1)) / m.sum();
    // Backward Euler on a rigid fall: v_k = (v_{k-1} - h g) / (1 + h alpha)
    // (mass damping; stiffness damping and elastic forces vanish), x_k =
    // x_{k-1} + h v_k.
    const double h = sim.options().timeStep, alpha = sim.options().material.massDamping;
    double v = 0, y = 0;
    for (int i = 0; i < 6; ++i) {
      v = (v - h * 9.81) / (1 + h * alpha);
      y += h * v;
    }
    EXPECT_NEAR(fallen, y, 1e-6 * std::abs(y));
  }
  {  // Twice the push, twice the sideways swing (linear at this amplitude).
    auto swing = [&](double acceleration) {
      ScenarioParameters p;
      p.pushAcceleration = acceleration;
      SimulationOptions options;
      options.gravity.setZero();
      Simulation sim(d.mesh, 0, options);
      auto wobble = makeScenario("wobble", p);
      wobble->setUp(sim);
      for (int i = 0; i < 8; ++i) {
        wobble->beforeStep(sim, sim.time());
        sim.step();
      }
      return sim.state().positions(top, 0) - rest.nodes(top, 0);
    };
    const double one = swing(1), two = swing(2);
    EXPECT_GT(one, 1e-5);
    EXPECT_NEAR(two, 2 * one, 0.02 * one);
  }
  for (auto spoil : std::vector<std::function<void(ScenarioParameters&)>>{
           [](ScenarioParameters& p) { p.baseShare = 1; },
           [](ScenarioParameters& p) { p.baseShare = -0.1; },
           [](ScenarioParameters& p) { p.pushFrequency = 0; },
           [](ScenarioParameters& p) { p.twistSeconds = -1; },
           [](ScenarioParameters& p) { p.dropHeight = std::numeric_limits<double>::quiet_NaN(); },
           [](ScenarioParameters& p) { p.pushAcceleration = INFINITY; },
           [](ScenarioParameters& p) { p.loadSeconds = 0; },
           [](ScenarioParameters& p) {
             p.loadSeconds = std::numeric_limits<double>::quiet_NaN();
           }}) {
    ScenarioParameters p;
    spoil(p);
    EXPECT_THROW(makeScenario("wobble", p), Error);
  }
  ScenarioParameters missing;
  missing.fixedNodes = {static_cast<int>(rest.nodeCount())};
  Simulation sim(d.mesh, 0, SimulationOptions{});
  EXPECT_THROW(makeScenario("sag", missing)->setUp(sim), Error);
}

// scenariosReading() tells the truth: a parameter changes the run of
// exactly the scenarios it names (the command line refuses, and the GUI
// hides, it for the others).
TEST(Simulation, ScenarioParametersChangeExactlyTheScenariosThatReadThem) {
  const Dataset& d = sampleDataset();
  const TetMesh rest = extractLevel(d.mesh, 0);
  auto run = [&](const std::string& name, const ScenarioParameters& p) {
    Simulation sim(d.mesh, 0, scenarioOptions(name, SimulationOptions{}, rest));
    auto scenario = makeScenario(name, p);
    scenario->setUp(sim);
    for (int i = 0; i < 5; ++i) {
      scenario->beforeStep(sim, sim.time());
      sim.step();
    }
    return Points3(sim.state().positions);
  };
  const std::vector<std::pair<ScenarioParameter, std::function<void(ScenarioParameters&)>>>
      changes = {
          {ScenarioParameter::BaseShare, [](ScenarioParameters& p) { p.baseShare = 0.3; }},
          {ScenarioParameter::PushAcceleration,
           [](ScenarioParameters& p) { p.pushAcceleration = 40; }},
          {ScenarioParameter::PushFrequency, [](ScenarioParameters& p) { p.pushFrequency = 3; }},
          {ScenarioParameter::DropHeight, [](ScenarioParameters& p) { p.dropHeight = 0.6; }},
          {ScenarioParameter::TwistDegrees, [](ScenarioParameters& p) { p.twistDegrees = 30; }},
          {ScenarioParameter::TwistSeconds, [](ScenarioParameters& p) { p.twistSeconds = 0.3; }}};
  const std::vector<std::string> names = scenarioNames();
  for (const std::string& name : names) {
    const Points3 plain = run(name, {});
    for (const auto& [parameter, change] : changes) {
      ScenarioParameters p;
      change(p);
      const double moved = (run(name, p) - plain).norm();
      EXPECT_EQ(moved > 1e-9, scenarioReads(name, parameter))
          << name << ", parameter " << static_cast<int>(parameter) << ": moved " << moved;
    }
  }
  for (const auto& [parameter, change] : changes)
    for (const std::string& reader : scenariosReading(parameter))
      EXPECT_NE(std::find(names.begin(), names.end(), reader), names.end()) << reader;
}

TEST(Simulation, WobbleMovesTheTopBackAndForth) {
  const Dataset& d = sampleDataset();
  for (SolverKind solver : {SolverKind::ConjugateGradient, SolverKind::Multigrid}) {
    SimulationOptions options;
    options.solver = solver;
    Simulation sim(d.mesh, 1, options);
    auto wobble = makeScenario("wobble");
    wobble->setUp(sim);
    double minX = 1e9, maxX = -1e9;
    Index top = 0;
    sim.restMesh().nodes.col(1).maxCoeff(&top);
    for (int i = 0; i < 90; ++i) {
      wobble->beforeStep(sim, sim.time());
      const StepStats s = sim.step();
      EXPECT_LE(s.residual, options.tolerance);
      const double x = sim.state().positions(top, 0) - sim.restMesh().nodes(top, 0);
      minX = std::min(minX, x);
      maxX = std::max(maxX, x);
    }
    EXPECT_GT(maxX, 0.05) << toString(solver);
    EXPECT_LT(minX, -0.05) << toString(solver);
  }
}

// A box adds the nodes inside it (faces included) to the held ones, each
// once and sorted; a box inside out, or around no node, is an error naming
// the box (and the level's extent).
TEST(Simulation, HeldNodesInABoxJoinTheHeldOnes) {
  const TetMesh block = test::tetGrid(2, 1, 1, {2, 1, 1});  // x = 0, 1, 2
  BoundingBox end;
  end.min = {-1, -1, -1};
  end.max = {0, 5, 5};  // the face x = 0: 4 nodes
  const std::vector<int> box = fixedWithNodesInBox({}, block.nodes, end);
  ASSERT_EQ(box.size(), 4u);
  for (int node : box) EXPECT_EQ(block.nodes(node, 0), 0.0);
  EXPECT_TRUE(std::is_sorted(box.begin(), box.end()));
  const int other = static_cast<int>(block.nodeCount()) - 1;  // at x = 2
  std::vector<int> withOther = box;
  withOther.push_back(other);
  EXPECT_EQ(fixedWithNodesInBox({box[1], other}, block.nodes, end), withOther);

  BoundingBox outside;
  outside.min = {3, 0, 0};
  outside.max = {4, 1, 1};
  EXPECT_EQ(test::errorText([&] { fixedWithNodesInBox({}, block.nodes, outside); }),
            "no node of the level lies in 3,0,0 .. 4,1,1 (the level spans 0,0,0 .. 2,1,1)");
  BoundingBox insideOut;
  insideOut.min = {1, 0, 0};
  insideOut.max = {0, 1, 1};
  EXPECT_EQ(test::errorText([&] { fixedWithNodesInBox({}, block.nodes, insideOut); }),
            "its minimum 1,0,0 exceeds its maximum 0,1,1 along an axis");
}

// makeScenario() refuses each scenario parameter out of its range, NaN
// and infinity included, naming it and its value (the GUI passes what its
// fields hold; the command line checked each number already).
TEST(Simulation, ScenarioParametersOutOfRangeAreErrorsNamingTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::function<void(ScenarioParameters&)>, std::string>> cases = {
      {[](auto& p) { p.baseShare = 1; }, "the base share must be in [0, 1), got 1"},
      {[](auto& p) { p.baseShare = -0.1; }, "the base share must be in [0, 1), got -0.1"},
      {[&](auto& p) { p.baseShare = nan; }, "the base share"},
      {[&](auto& p) { p.pushAcceleration = inf; }, "the push acceleration must be finite"},
      {[](auto& p) { p.pushFrequency = 0; }, "the push frequency must be finite and > 0, got 0"},
      {[](auto& p) { p.dropHeight = -1; }, "the drop height must be finite and >= 0, got -1"},
      {[&](auto& p) { p.twistDegrees = nan; }, "the twist angle must be finite"},
      {[&](auto& p) { p.twistSeconds = inf; }, "the twist time must be finite and > 0"},
      {[&](auto& p) { p.loads = Points3::Constant(2, 3, nan); }, "the loads must be finite"},
      {[](auto& p) { p.loadSeconds = 0; }, "the time the loads act must be > 0, got 0"},
      {[](auto& p) {
         p.loadCurve = LoadCurve({{0, 1}});
       },
       "a load curve scales the loads, but there are none"},
  };
  for (const std::string& name : scenarioNames()) {
    EXPECT_NO_THROW(makeScenario(name, ScenarioParameters{})) << name;
    for (const auto& [spoil, message] : cases) {
      ScenarioParameters p;
      spoil(p);
      try {
        makeScenario(name, p);
        ADD_FAILURE() << name << ": no error for '" << message << "'";
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << name << ": " << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace tetskin
