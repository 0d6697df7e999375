// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <regex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ExpectError.h"
#include "SampleData.h"
#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

MultiLevelTetMesh oneLevel(const TetMesh& mesh) {
  MultiLevelTetMesh m;
  appendLevel(m, mesh);
  return m;
}

std::vector<int> nodesWithXBelow(const TetMesh& mesh, double x) {
  std::vector<int> nodes;
  for (Index v = 0; v < mesh.nodeCount(); ++v)
    if (mesh.nodes(v, 0) <= x) nodes.push_back(static_cast<int>(v));
  return nodes;
}

// A cantilever along x, clamped at x = 0, for the Euler-Bernoulli tests:
// linear tetrahedra are too stiff in bending and converge from below (under
// its own weight 40x4x4 cubes give -17%, 60x6x6 -8%, 80x8x8 -4.4%).
constexpr double kBeamLength = 10, kBeamWidth = 1, kBeamHeight = 1;
constexpr double kBeamInertia = kBeamWidth * kBeamHeight * kBeamHeight * kBeamHeight / 12;  // I

// The nodes of the free end (x = L).
std::vector<Index> freeEnd(const TetMesh& beam) {
  std::vector<Index> end;
  for (Index v = 0; v < beam.nodeCount(); ++v)
    if (beam.nodes(v, 0) >= kBeamLength - 1e-9) end.push_back(v);
  return end;
}

// The beam clamped at x = 0 (no base: it is a share of the height) with a
// load of P newtons down spread over the free end.
ScenarioParameters tipLoaded(const TetMesh& beam, double P) {
  ScenarioParameters p;
  p.baseShare = 0;
  p.heldNodes = nodesWithXBelow(beam, 1e-9);
  p.loads = Points3::Zero(beam.nodeCount(), 3);
  const std::vector<Index> end = freeEnd(beam);
  for (Index v : end) p.loads(v, 1) = -P / static_cast<double>(end.size());
  return p;
}

// The free end's mean downward deflection.
double tipDeflection(const TetMesh& beam, const Points3& positions) {
  const std::vector<Index> end = freeEnd(beam);
  double tip = 0;
  for (Index v : end) tip += beam.nodes(v, 1) - positions(v, 1);
  return tip / static_cast<double>(end.size());
}

// The beams' material: E = 1e6 Pa, no Poisson effect (Euler-Bernoulli
// has none), density 1, damping by the mass only.
ElasticMaterial beamMaterial(double massDamping) {
  ElasticMaterial material;
  material.youngsModulus = 1e6;
  material.poissonRatio = 0.0;
  material.density = 1;
  material.massDamping = massDamping;
  material.stiffnessDamping = 0;
  return material;
}

// The dynamics tests' beam: weightless and undamped but for backward
// Euler's own damping, about 60 steps per period of its first mode.
SimulationOptions swingingBeamOptions() {
  SimulationOptions options;
  options.material = beamMaterial(0);
  options.gravity.setZero();
  options.timeStep = 0.01;
  options.tolerance = 1e-7;
  return options;
}

// Euler-Bernoulli's first natural frequency of the cantilever,
// (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)), in Hz.
double firstNaturalFrequency(const ElasticMaterial& material) {
  const double A = kBeamWidth * kBeamHeight;
  return 1.8751 * 1.8751 / (2 * M_PI) *
         std::sqrt(material.youngsModulus * kBeamInertia /
                   (material.density * A * std::pow(kBeamLength, 4)));
}

// Euler-Bernoulli's tip deflection under a tip load P, P L^3 / (3 E I).
double tipLoadDeflection(const ElasticMaterial& material, double P) {
  return P * std::pow(kBeamLength, 3) / (3 * material.youngsModulus * kBeamInertia);
}

// Runs `beam` in the sag scenario with `p` (its held nodes, loads and load
// curve) until `until` seconds, checking that each step's external forces
// are the loads times the curve's factor at the step's start; the largest
// |tip deflection| after `from` seconds.
double peakTipDeflection(const TetMesh& beam, const SimulationOptions& options,
                         const ScenarioParameters& p, double from, double until) {
  Simulation sim(oneLevel(beam), 0, options);
  const auto sag = makeScenario("sag", p);
  sag->setUp(sim);
  double peak = 0;
  while (sim.time() < until) {
    const double t = sim.time();
    sag->beforeStep(sim, t);
    EXPECT_TRUE(sim.externalForces().isApprox(p.loadCurve.factorAt(t) * p.loads)) << "t = " << t;
    sim.step();
    if (sim.time() > from)
      peak = std::max(peak, std::abs(tipDeflection(beam, sim.state().positions)));
  }
  return peak;
}

TetMesh cantilever() {
  return test::tetGrid(80, 8, 8, {kBeamLength, kBeamHeight, kBeamWidth});
}

// Large implicit steps, heavily damped, march to the static equilibrium.
SimulationOptions staticBeamOptions() {
  SimulationOptions options;
  options.material = beamMaterial(5);
  options.timeStep = 1.0;
  options.tolerance = 1e-10;
  options.solver = SolverKind::ConjugateGradient;
  return options;
}

// Steps until the tip (the nodes at x = L) settles; its mean downward
// deflection. `scenario`, if any, is set up and drives each step.
double settledTipDeflection(Simulation& sim, Scenario* scenario) {
  const TetMesh& beam = sim.restMesh();
  if (scenario) scenario->setUp(sim);
  double previous = 0, tip = 0;
  for (int i = 0; i < 60; ++i) {
    if (scenario) scenario->beforeStep(sim, sim.time());
    sim.step();
    tip = tipDeflection(beam, sim.state().positions);
    if (std::abs(tip - previous) < 1e-9 * std::abs(tip)) break;
    previous = tip;
  }
  return tip;
}

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

// A free 6 x 1 x 1 bar (E = 1e6 Pa, density 1) pulled at both ends by an
// axial stress of 1e-3 E: opposite end forces, equal on each of the 16 end
// nodes.
const TetMesh& pulledBar() {
  static const TetMesh bar = test::tetGrid(12, 3, 3, {6, 1, 1});
  return bar;
}

SimulationOptions pulledBarOptions(double poissonRatio, double timeStep) {
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 1e6;
  options.material.poissonRatio = poissonRatio;
  options.material.density = 1;
  options.material.massDamping = 5;
  options.material.stiffnessDamping = 0;
  options.timeStep = timeStep;
  options.tolerance = 1e-10;
  options.solver = SolverKind::ConjugateGradient;
  return options;
}

void pullBar(Simulation& sim) {
  const TetMesh& bar = sim.restMesh();
  Points3 forces = Points3::Zero(bar.nodeCount(), 3);
  for (Index v = 0; v < bar.nodeCount(); ++v) {
    if (bar.nodes(v, 0) < 1e-9) forces(v, 0) = -1e3 / 16;
    if (bar.nodes(v, 0) > 6 - 1e-9) forces(v, 0) = 1e3 / 16;
  }
  sim.setExternalForces(forces);
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

TEST(Simulation, UndampedEnergyNeverRisesAndDampedEnergyDecays) {
  const TetMesh block = test::tetGrid(4, 2, 2, {2, 1, 1});
  for (bool damped : {false, true}) {
    SimulationOptions options;
    options.material.youngsModulus = 1e4;
    options.material.density = 10;
    options.material.massDamping = damped ? 0.5 : 0.0;
    options.material.stiffnessDamping = damped ? 0.01 : 0.0;
    options.gravity.setZero();
    options.tolerance = 1e-12;
    Simulation sim(oneLevel(block), 0, options);
    Points3 squashed = block.nodes;
    squashed.col(0) *= 1.3;  // stretched: starts with elastic energy
    sim.setPositions(squashed);
    double energy = sim.energies().total();
    const double initial = energy;
    for (int i = 0; i < 120; ++i) {
      sim.step();
      const double next = sim.energies().total();
      // One linearized step per time step (the tangent R K R^T leaves out
      // dR/dx) is not exactly dissipative: rises stay at round-off level,
      // about 3e-11 of the initial energy here.
      EXPECT_LE(next - energy, 1e-10 * initial) << "step " << i << (damped ? " damped" : "");
      energy = next;
    }
    if (damped) {
      EXPECT_LT(energy, 0.05 * initial);
    }
  }
}

// Gravitational energy is measured from the rest shape: none there, m g d
// for the body lifted by d (a rigid lift: no elastic energy), the same
// however far the rest shape lies from the origin.
TEST(Simulation, GravitationalEnergyIsMeasuredFromTheRestShape) {
  for (double offset : {0.0, 1e3}) {
    TetMesh block = test::tetGrid(3, 2, 2, {1.5, 1, 1});
    block.nodes.col(1).array() += offset;
    SimulationOptions options;
    options.gravity = {0, -9.81, 0};
    Simulation sim(oneLevel(block), 0, options);
    const Energies atRest = sim.energies();
    EXPECT_EQ(atRest.kinetic, 0);
    EXPECT_EQ(atRest.gravitational, 0) << "offset " << offset;
    EXPECT_LT(std::abs(atRest.elastic), 1e-12);
    Points3 lifted = block.nodes;
    lifted.col(1).array() += 0.25;
    sim.setPositions(lifted);
    const double mass = sim.nodeMasses().sum();
    EXPECT_GT(mass, 0);
    EXPECT_NEAR(sim.energies().gravitational, mass * 9.81 * 0.25, 1e-9 * mass * 9.81 * 0.25)
        << "offset " << offset;
    EXPECT_LT(std::abs(sim.energies().elastic), 1e-9);
  }
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
    EXPECT_GE(boundingBox(x).min.y(), *options.floorHeight - 1e-9);
    EXPECT_LT(boundingBox(x).min.y(), *options.floorHeight + 0.05);  // resting on it
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
  for (const char* name : {"wobble", "drop", "twist", "sag"}) {
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
  held.heldNodes = {static_cast<int>(top)};
  for (const std::string& name : scenarioNames()) {
    Simulation sim(d.mesh, 0, scenarioOptions(name, SimulationOptions{}, rest));
    auto scenario = makeScenario(name, held);
    scenario->setUp(sim);
    const std::vector<int>& fixed = sim.fixedNodes();
    EXPECT_TRUE(std::is_sorted(fixed.begin(), fixed.end())) << name;
    EXPECT_TRUE(std::binary_search(fixed.begin(), fixed.end(), static_cast<int>(top))) << name;
    // The base (all but drop) is still fixed besides.
    EXPECT_EQ(std::binary_search(fixed.begin(), fixed.end(), static_cast<int>(bottom)),
              name != "drop")
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
  missing.heldNodes = {static_cast<int>(rest.nodeCount())};
  Simulation sim(d.mesh, 0, SimulationOptions{});
  EXPECT_THROW(makeScenario("sag", missing)->setUp(sim), Error);
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

// A box adds the nodes inside it (faces included) to the held ones, each
// once and sorted; a box inside out, or around no node, is an error naming
// the box (and the level's extent).
TEST(Simulation, HeldNodesInABoxJoinTheHeldOnes) {
  const TetMesh block = test::tetGrid(2, 1, 1, {2, 1, 1});  // x = 0, 1, 2
  BoundingBox end;
  end.min = {-1, -1, -1};
  end.max = {0, 5, 5};  // the face x = 0: 4 nodes
  const std::vector<int> box = heldWithNodesInBox({}, block.nodes, end);
  ASSERT_EQ(box.size(), 4u);
  for (int node : box) EXPECT_EQ(block.nodes(node, 0), 0.0);
  EXPECT_TRUE(std::is_sorted(box.begin(), box.end()));
  const int other = static_cast<int>(block.nodeCount()) - 1;  // at x = 2
  std::vector<int> withOther = box;
  withOther.push_back(other);
  EXPECT_EQ(heldWithNodesInBox({box[1], other}, block.nodes, end), withOther);

  BoundingBox outside;
  outside.min = {3, 0, 0};
  outside.max = {4, 1, 1};
  EXPECT_EQ(test::errorText([&] { heldWithNodesInBox({}, block.nodes, outside); }),
            "no node of the level lies in 3,0,0 .. 4,1,1 (the level spans 0,0,0 .. 2,1,1)");
  BoundingBox insideOut;
  insideOut.min = {1, 0, 0};
  insideOut.max = {0, 1, 1};
  EXPECT_EQ(test::errorText([&] { heldWithNodesInBox({}, block.nodes, insideOut); }),
            "its minimum 1,0,0 exceeds its maximum 0,1,1 along an axis");
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
      {[&](auto& o) { o.friction = 1.5; }, "friction"},
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

}  // namespace
}  // namespace tetskin
