// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole simulation runs: known answers of elasticity: the cantilever against Euler-Bernoulli
// (static, loaded, vibrating, ramped and resonant loads), the pulled bar against Young's modulus
// and Poisson's ratio, the supports' reactions, the full tangent under large steps.
#include "SimulationBodies.h"

namespace tetskin {
namespace {

using namespace test;

// Euler-Bernoulli: a cantilever of length L under its own weight q per length
// deflects q L^4 / (8 E I) at the tip, I = b h^3 / 12.
TEST(Simulation, CantileverMatchesEulerBernoulli) {
  const double L = kBeamLength, b = kBeamWidth, h = kBeamHeight;
  const TetMesh beam = cantilever();
  const SimulationOptions options = staticBeamOptions();
  Simulation sim(oneLevel(beam), 0, options);
  sim.setFixedNodes(nodesWithXBelow(beam, 1e-9));
  const double tip = settledTipDeflection(sim, nullptr);
  const double q = options.material.density * 9.81 * b * h;
  const double expected = q * std::pow(L, 4) / (8 * options.material.youngsModulus * kBeamInertia);
  std::printf("cantilever tip deflection: simulated %.5f, Euler-Bernoulli %.5f (%.1f%%)\n", tip,
              expected, 100 * (tip - expected) / expected);
  EXPECT_NEAR(tip, expected, 0.1 * expected);
  EXPECT_LT(tip, expected * 1.02);  // linear tetrahedra are, if anything, too stiff
}

// The supports' reactions: at rest before any step the held nodes carry
// only their own weight; once the cantilever has settled its clamp carries
// the whole weight W (up) and the moment W L / 2 about it, with the
// deformed positions: the reactions and gravity are in equilibrium, forces
// and moments. Free nodes have none.
TEST(Simulation, ReactionsOfASettledCantileverCarryItsWeightAndMoment) {
  const double L = kBeamLength;
  const TetMesh beam = test::tetGrid(20, 2, 2, {L, kBeamHeight, kBeamWidth});
  const SimulationOptions options = staticBeamOptions();
  Simulation sim(oneLevel(beam), 0, options);
  const std::vector<int> clamp = nodesWithXBelow(beam, 1e-9);
  sim.setFixedNodes(clamp);
  const Eigen::VectorXd mass = sim.nodeMasses();
  const double weight = mass.sum() * 9.81;
  ASSERT_NEAR(weight, options.material.density * 9.81 * L * kBeamHeight * kBeamWidth, 1e-9);
  auto isClamped = [&](Index v) { return std::find(clamp.begin(), clamp.end(), v) != clamp.end(); };

  const Points3 atRest = sim.reactionForces(sim.state());
  for (Index v = 0; v < beam.nodeCount(); ++v) {
    const Eigen::Vector3d expected(0, isClamped(v) ? mass[v] * 9.81 : 0, 0);
    EXPECT_LT((atRest.row(v).transpose() - expected).norm(), 1e-12 * weight) << v;
  }

  settledTipDeflection(sim, nullptr);
  const FrameFields settled = sim.frameFields(sim.state());
  EXPECT_EQ(settled.reactionForces, sim.reactionForces(sim.state()));
  EXPECT_EQ(sim.supportReaction(sim.state()),
            settled.reactionForces.colwise().sum().transpose().eval());
  EXPECT_EQ(settled.positions, sim.state().positions);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero(),
                  clampMoment = Eigen::Vector3d::Zero();
  for (Index v = 0; v < beam.nodeCount(); ++v) {
    const Eigen::Vector3d x = settled.positions.row(v).transpose();
    const Eigen::Vector3d reaction = settled.reactionForces.row(v).transpose();
    const Eigen::Vector3d gravity = mass[v] * options.gravity;
    if (!isClamped(v)) {
      EXPECT_EQ(reaction, Eigen::Vector3d::Zero()) << v;
    }
    force += reaction + gravity;
    moment += x.cross(reaction + gravity);
    clampMoment += x.cross(reaction);
  }
  std::printf(
      "settled cantilever: reactions %.6f N up (weight %.6f), clamp moment %.6f N m "
      "(W L / 2 = %.6f)\n",
      force.y() + weight, weight, clampMoment.z(), weight * L / 2);
  EXPECT_LT(force.norm(), 1e-6 * weight);
  EXPECT_LT(moment.norm(), 1e-6 * weight * L);
  // The beam has shortened a little along x as it bent: the moment is that
  // of the weight at its deformed centre, within 0.5% of W L / 2.
  EXPECT_NEAR(clampMoment.z(), weight * L / 2, 5e-3 * weight * L / 2);
}

// The inertia and damping in the reactions, which a settled body has none
// of: every node of a body driven (kinematic targets) along a uniformly
// accelerated translation, x(t) = X + a t^2 / 2 (no strain, no strain
// rate), is held by its support alone, r = m (a + alpha v - g) per node.
// The step's acceleration is the second difference of the targets, exactly
// a, from the second step on; the first starts from rest with v = a h / 2.
// A new start (setVelocities) has no acceleration of a step behind it.
TEST(Simulation, ReactionsOfADrivenBodyAreItsMassTimesAcceleration) {
  const TetMesh body = test::tetGrid(3, 2, 2, {3, 2, 2});
  SimulationOptions options;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-12;
  const double h = options.timeStep, alpha = options.material.massDamping;
  Simulation sim(oneLevel(body), 0, options);
  std::vector<int> all(static_cast<std::size_t>(body.nodeCount()));
  for (int v = 0; v < body.nodeCount(); ++v) all[static_cast<std::size_t>(v)] = v;
  sim.setFixedNodes(all);
  const Eigen::Vector3d a(2.0, -1.0, 0.5);
  const Eigen::VectorXd mass = sim.nodeMasses();
  for (int step = 1; step <= 5; ++step) {
    const double t = step * h;
    sim.setKinematicTargets(all, body.nodes.rowwise() + 0.5 * t * t * a.transpose());
    sim.step();
    const SimulationState state = sim.state();
    const Eigen::Vector3d velocity = (step - 0.5) * h * a;  // (x(t) - x(t - h)) / h
    const Eigen::Vector3d acceleration = step == 1 ? Eigen::Vector3d(0.5 * a) : a;
    const Points3 reactions = sim.reactionForces(state);
    for (Index v = 0; v < body.nodeCount(); ++v) {
      const Eigen::Vector3d expected =
          mass[v] * (acceleration + alpha * velocity - options.gravity);
      EXPECT_LT((reactions.row(v).transpose() - expected).norm(), 1e-9 * expected.norm())
          << "step " << step << ", node " << v;
    }
  }
  sim.setVelocities(sim.state().velocities);
  const SimulationState restarted = sim.state();
  EXPECT_EQ(restarted.accelerations, Points3::Zero(body.nodeCount(), 3));
  EXPECT_LT((sim.reactionForces(restarted).row(0).transpose() -
             mass[0] * (alpha * restarted.velocities.row(0).transpose() - options.gravity))
                .norm(),
            1e-9 * mass[0] * options.gravity.norm());
}

// In motion, the reactions balance the whole body's momentum: internal
// forces sum to zero, so the supports supply sum m (a + alpha v - g) less
// the external forces, to within what the step's linearized force leaves
// (about 1e-4 of the weight here). A sag on the bunny's 12.7k level sways
// the asymmetric body sideways as it settles: the reaction's x part is as
// large as 8% of its weight, and balances too.
TEST(Simulation, ReactionsBalanceTheBodysChangeOfMomentum) {
  SimulationOptions options;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-10;
  Simulation sim(sampleDataset().mesh, 2, options);
  std::unique_ptr<Scenario> sag = makeScenario("sag");
  sag->setUp(sim);
  const Eigen::VectorXd mass = sim.nodeMasses();
  const double weight = mass.sum() * options.gravity.norm();
  double largestSideways = 0;
  for (int step = 1; step <= 30; ++step) {
    sag->beforeStep(sim, sim.time());
    sim.step();
    const SimulationState state = sim.state();
    Eigen::Vector3d needed = Eigen::Vector3d::Zero();
    for (Index v = 0; v < mass.size(); ++v)
      needed += mass[v] * (state.accelerations.row(v).transpose() +
                           options.material.massDamping * state.velocities.row(v).transpose() -
                           options.gravity) -
                state.externalForces.row(v).transpose();
    const Eigen::Vector3d reaction = sim.supportReaction(state);
    EXPECT_LT((reaction - needed).norm(), 1e-3 * weight) << "step " << step;
    largestSideways = std::max(largestSideways, std::abs(reaction.x()));
  }
  EXPECT_GT(largestSideways, 0.05 * weight);  // (the balance is not of zeros)
}

// The pulled bar (uniaxial stress) stretches by stress / E and narrows by
// Poisson's ratio times that, or widens for an auxetic nu < 0: linear
// tetrahedra represent the uniform strain exactly, and the middle third of
// the bar is two widths from the loaded ends.
TEST(Simulation, PulledBarStretchesByYoungsModulusAndNarrowsByPoissonsRatio) {
  const TetMesh& bar = pulledBar();
  for (double nu : {-0.5, 0.0, 0.3, 0.45}) {
    // Steps of 0.01 s: stiff modes are damped out within a few steps.
    Simulation sim(oneLevel(bar), 0, pulledBarOptions(nu, 0.01));
    pullBar(sim);
    for (int i = 0; i < 100; ++i) sim.step();
    const Points3 x = sim.state().positions;
    // Mean of coordinate `axis` over the middle third's nodes on a grid plane.
    auto mean = [&](int axis, int planeAxis, double plane) {
      double sum = 0;
      int count = 0;
      for (Index v = 0; v < bar.nodeCount(); ++v)
        if (std::abs(bar.nodes(v, planeAxis) - plane) < 1e-9 &&
            std::abs(bar.nodes(v, 0) - 3) <= 1 + 1e-9) {
          sum += x(v, axis);
          ++count;
        }
      return sum / count;
    };
    const double axial = ((mean(0, 0, 4) - mean(0, 0, 2)) - 2) / 2;  // x = 2..4
    const double lateral = (mean(1, 1, 1) - mean(1, 1, 0)) - 1;      // y = 0..1
    EXPECT_NEAR(axial, 1e-3, 0.02e-3) << "nu " << nu;
    EXPECT_NEAR(-lateral / axial, nu, 0.01) << "nu " << nu;
  }
}

// The pulled bar with steps of 1 s, a hundred times the test above's. With
// the full tangent it stays straight and settles at the length the small
// steps give (6.0068 m for nu = 0, 6.0069 for 0.3); with R K R^T
// alone (stiffness warping) each step overshoots the rotations that the
// bar's tension resists, and it blows up within a few steps.
TEST(Simulation, FullTangentKeepsAStretchedFreeBarSteadyUnderLargeSteps) {
  for (const Tangent tangent : {Tangent::Full, Tangent::Warped}) {
    for (double nu : {0.0, 0.3}) {
      SimulationOptions options = pulledBarOptions(nu, 1.0);
      options.tangent = tangent;
      Simulation sim(oneLevel(pulledBar()), 0, options);
      pullBar(sim);
      double widest = 0, length = 0;
      for (int i = 0; i < 12; ++i) {
        try {
          sim.step();
        } catch (const Error&) {  // "the simulation diverged"
          widest = std::numeric_limits<double>::infinity();
          break;
        }
        const Points3 x = sim.state().positions;
        widest = std::max(widest, x.col(1).maxCoeff() - x.col(1).minCoeff());
        length = x.col(0).maxCoeff() - x.col(0).minCoeff();
      }
      std::printf("tangent %s, nu %g: widest lateral extent %.4g m, final length %.5g m\n",
                  toString(tangent), nu, widest, length);
      if (tangent == Tangent::Full) {
        EXPECT_LT(widest, 1 + 1e-3) << "nu " << nu;
        EXPECT_NEAR(length, 6.0069, 1e-3) << "nu " << nu;
      } else {
        EXPECT_GT(widest, 2) << "nu " << nu;
      }
    }
  }
}

// Loads (ScenarioParameters::loads, `simulate --loads`): a force P spread
// over the free end's nodes bends the cantilever by P L^3 / (3 E I), and
// loads equal to each node's weight reproduce gravity.
TEST(Simulation, LoadsBendACantileverAndActAsWeight) {
  const TetMesh beam = cantilever();
  SimulationOptions options = staticBeamOptions();
  options.gravity.setZero();
  Simulation sim(oneLevel(beam), 0, options);
  const auto sag = makeScenario("sag", tipLoaded(beam, 0.5));
  const double tip = settledTipDeflection(sim, sag.get());
  const double expected = tipLoadDeflection(options.material, 0.5);
  std::printf("tip load deflection: simulated %.5f, Euler-Bernoulli %.5f (%.1f%%)\n", tip, expected,
              100 * (tip - expected) / expected);
  EXPECT_NEAR(tip, expected, 0.1 * expected);
  EXPECT_LT(tip, expected * 1.02);

  // Weight as loads: m_i g on every node with gravity off, against gravity.
  const Dataset& d = sampleDataset();
  const TetMesh rest = extractLevel(d.mesh, 0);
  auto sagged = [&](const SimulationOptions& o, const ScenarioParameters& p) {
    Simulation s(d.mesh, 0, o);
    const auto scenario = makeScenario("sag", p);
    scenario->setUp(s);
    for (int i = 0; i < 8; ++i) {
      scenario->beforeStep(s, s.time());
      s.step();
    }
    return Points3(s.state().positions);
  };
  const SimulationOptions withGravity;
  SimulationOptions weightless;
  weightless.gravity.setZero();
  ScenarioParameters weights;
  weights.loads = Points3::Zero(rest.nodeCount(), 3);
  weights.loads.col(1) = Simulation(d.mesh, 0, weightless).nodeMasses() * -9.81;
  const Points3 byGravity = sagged(withGravity, {});
  const Points3 byLoads = sagged(weightless, weights);
  EXPECT_GT((byGravity - rest.nodes).norm(), 1e-3);  // it did sag
  EXPECT_LT((byLoads - byGravity).norm(), 1e-6 * (byGravity - rest.nodes).norm());

  // Loads of another level are refused when the scenario is set up.
  ScenarioParameters wrong;
  wrong.loads = Points3::Zero(rest.nodeCount() + 1, 3);
  Simulation other(d.mesh, 0, SimulationOptions{});
  EXPECT_THROW(makeScenario("sag", wrong)->setUp(other), Error);
}

// Dynamics with a known answer: a cantilever let go after a tip load
// (ScenarioParameters::loadSeconds) vibrates at Euler-Bernoulli's first
// natural frequency, (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)).
TEST(Simulation, ReleasedCantileverVibratesAtItsFirstNaturalFrequency) {
  const TetMesh beam = test::tetGrid(60, 6, 6, {kBeamLength, kBeamHeight, kBeamWidth});
  const SimulationOptions options = swingingBeamOptions();
  ScenarioParameters plucked = tipLoaded(beam, 0.5);
  plucked.loadSeconds = 0.2;
  Simulation sim(oneLevel(beam), 0, options);
  const auto sag = makeScenario("sag", plucked);
  sag->setUp(sim);
  // Upward zero crossings of the free end's mean height after the release.
  std::vector<double> crossings;
  double previous = 0;
  while (sim.time() < 2.0) {
    sag->beforeStep(sim, sim.time());
    sim.step();
    const double tip = -tipDeflection(beam, sim.state().positions);  // up
    const double t = sim.time();
    if (t > plucked.loadSeconds + options.timeStep && previous < 0 && tip >= 0)
      crossings.push_back(t - options.timeStep * tip / (tip - previous));
    previous = tip;
  }
  ASSERT_GE(crossings.size(), 3u) << "the free end did not swing";
  const double period =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double expected = firstNaturalFrequency(options.material);
  std::printf("first natural frequency: simulated %.4f Hz, Euler-Bernoulli %.4f Hz (%.1f%%)\n",
              1 / period, expected, 100 * (1 / period - expected) / expected);
  EXPECT_NEAR(1 / period, expected, 0.1 * expected);
}

// Load curves (ScenarioParameters::loadCurve, `simulate --load-curve`),
// against structural dynamics' known answer for an undamped beam: a load
// put on at once swings the tip to twice its static deflection (less the
// damping of backward Euler itself), one ramped up over a natural period T
// or longer barely past it (the peak factor of a ramp of rise time t_r is
// 1 + |sin(pi t_r / T)| / (pi t_r / T): 1 at t_r = T). Each step's external
// forces are the loads times the curve's factor at the step's start.
TEST(Simulation, LoadCurveRampsALoadOnWithoutTheOvershootOfASuddenOne) {
  const TetMesh beam = test::tetGrid(60, 6, 6, {kBeamLength, kBeamHeight, kBeamWidth});
  const SimulationOptions options = swingingBeamOptions();
  const ScenarioParameters loaded = tipLoaded(beam, 0.5);
  const double period = 1 / firstNaturalFrequency(options.material);
  const double staticTip = tipLoadDeflection(options.material, 0.5);
  // The largest downward tip deflection within 1.5 periods after the ramp.
  auto peakTip = [&](const ScenarioParameters& p, double rise) {
    return peakTipDeflection(beam, options, p, 0, rise + 1.5 * period);
  };
  const double sudden = peakTip(loaded, 0) / staticTip;
  ScenarioParameters ramped = loaded;
  ramped.loadCurve = LoadCurve({{0, 0}, {period, 1}});
  const double ramp = peakTip(ramped, period) / staticTip;
  ScenarioParameters halved = loaded;  // a constant factor scales the answer
  halved.loadCurve = LoadCurve({{0, 0.5}});
  const double half = peakTip(halved, 0) / staticTip;
  std::printf(
      "peak tip over Euler-Bernoulli's static deflection: sudden load %.3f, ramped over T %.3f, "
      "half load %.3f\n",
      sudden, ramp, half);
  EXPECT_GT(sudden, 1.6);
  EXPECT_LT(sudden, 2.0);
  EXPECT_GT(ramp, 0.85);
  EXPECT_LT(ramp, 1.1);
  EXPECT_NEAR(half, sudden / 2, 0.01 * sudden);
}

// A repeated load curve (`repeat` in a --load-curve file) makes periodic
// forcing from one period's points: a tip load swinging as a sine at the
// beam's first natural frequency (Euler-Bernoulli's, 3.6% under the
// discretized beam's) builds up resonance, one at half that frequency
// barely moves the tip beyond its static deflection (1 / (1 - r^2) = 1.33x
// undamped); only backward Euler's own damping (about 10% of critical at
// 30 steps per period) bounds the resonance.
TEST(Simulation, RepeatedLoadCurveDrivesTheCantileverIntoResonance) {
  const TetMesh beam = test::tetGrid(60, 6, 6, {kBeamLength, kBeamHeight, kBeamWidth});
  SimulationOptions options = swingingBeamOptions();
  const double frequency = firstNaturalFrequency(options.material);
  options.timeStep = 1 / (30 * frequency);
  const double staticTip = tipLoadDeflection(options.material, 0.5);
  // The largest tip deflection in the last second of 2.5 s, in static ones.
  auto swing = [&](double hz) {
    std::vector<LoadCurve::Point> sine;
    for (int i = 0; i <= 24; ++i) sine.push_back({i / (24 * hz), std::sin(2 * M_PI * i / 24.0)});
    ScenarioParameters driven = tipLoaded(beam, 0.5);
    driven.loadCurve = LoadCurve(std::move(sine), LoadCurve::After::Repeat);
    return peakTipDeflection(beam, options, driven, 1.5, 2.5) / staticTip;
  };
  const double resonant = swing(frequency), slow = swing(frequency / 2);
  std::printf("peak tip over the static deflection, driven at f1: %.2f, at f1 / 2: %.2f\n",
              resonant, slow);
  EXPECT_GT(resonant, 2.5 * slow);  // (3.17x: the resonance still grows at 2.5 s)
  EXPECT_GT(resonant, 3);
  EXPECT_GT(slow, 0.8);
  EXPECT_LT(slow, 1.6);
}

}  // namespace
}  // namespace tetskin
