// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole runs against obstacles, each with a known answer: a block on an
// incline sticks when mu_s > tan(theta) and slides with acceleration
// g (sin theta - mu_k cos theta) when mu_k < tan(theta); a block at rest
// on a slab is held by contact forces equal to its weight, sunk by a
// fraction of its size; a paddle sweeping through pushes it along without
// it ending up inside; a rigid motion of body, obstacle and gravity
// together leaves the run unchanged; and the floor, the simplest obstacle,
// runs as a slab and stops a sliding block where Coulomb says.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "Shapes.h"
#include "SimulationBodies.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::test {
namespace {

// A 0.2 x 0.1 x 0.2 m block of soft rubber, its base on y = 0.
TetMesh block() {
  return tetGrid(4, 2, 4, {0.2, 0.1, 0.2});
}
constexpr double kBlockSize = 0.2;

// A slab whose top is y = 0 (or what `pose` makes of it).
Obstacle slab(double staticFriction, double kineticFriction, const ObstaclePose& pose = {}) {
  Obstacle o;
  o.name = "slab";
  o.shape = std::make_shared<ClosedSurfaceDistance>(box({-5, -1, -5}, {5, 0, 5}), o.name);
  o.placement = pose;
  o.staticFriction = staticFriction;
  o.kineticFriction = kineticFriction;
  return o;
}

SimulationOptions rubber(double theta) {
  SimulationOptions options;
  options.material.youngsModulus = 2e5;
  options.material.poissonRatio = 0.3;
  options.material.density = 1000;
  options.material.massDamping = 0;
  options.material.stiffnessDamping = 0.01;
  options.timeStep = 1.0 / 200;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-10;
  // Gravity tilted by theta: the slope runs down along +x.
  options.gravity = kStandardGravity * Eigen::Vector3d(std::sin(theta), -std::cos(theta), 0);
  return options;
}

Eigen::Vector3d mean(const Points3& rows) {
  return rows.colwise().mean().transpose();
}

TEST(ObstacleContact, ABlockOnAnInclineSticksWhenStaticFrictionHoldsIt) {
  const double theta = 20 * M_PI / 180;  // tan = 0.364
  SimulationOptions options = rubber(theta);
  options.obstacles = {slab(0.5, 0.45)};
  Simulation sim(oneLevel(block()), 0, options);
  // Landing: until the springs carry the weight (a few steps) the block
  // slides a little and shears; 0.25 s later it rests on the incline.
  for (int i = 0; i < 50; ++i) sim.step();
  const Eigen::Vector3d start = mean(sim.state().positions);
  for (int i = 0; i < 400; ++i) sim.step();  // 2 s
  const Eigen::Vector3d drift = mean(sim.state().positions) - start;
  EXPECT_LT(Eigen::Vector2d(drift.x(), drift.z()).norm(), 0.01 * kBlockSize) << drift.transpose();
  std::printf("drift along the slope over 2 s: %.3g of the block's size\n", drift.x() / kBlockSize);
}

TEST(ObstacleContact, ABlockOnAnInclineSlidesWithTheKineticAcceleration) {
  const double theta = 20 * M_PI / 180, mu = 0.2;
  SimulationOptions options = rubber(theta);
  options.obstacles = {slab(mu, mu)};
  Simulation sim(oneLevel(block()), 0, options);
  for (int i = 0; i < 100; ++i) sim.step();  // 0.5 s
  const double v1 = mean(sim.state().velocities).x();
  for (int i = 0; i < 200; ++i) sim.step();  // 1 s more
  const double v2 = mean(sim.state().velocities).x();
  const double expected = kStandardGravity * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR((v2 - v1) / 1.0, expected, 0.05 * expected);
}

TEST(ObstacleContact, ABlockAtRestIsHeldByItsWeightAndSinksLittle) {
  SimulationOptions options = rubber(0);
  options.material.massDamping = 2;  // to settle
  options.obstacles = {slab(0.5, 0.4)};
  const TetMesh body = block();
  Simulation sim(oneLevel(body), 0, options);
  for (int i = 0; i < 400; ++i) sim.step();
  const SimulationState state = sim.state();
  const Eigen::Vector3d support = sim.contactForces(state).colwise().sum().transpose();
  const double weight = sim.nodeMasses().sum() * kStandardGravity;
  EXPECT_NEAR(support.y(), weight, 0.01 * weight);
  EXPECT_NEAR(support.x(), 0, 1e-6 * weight);
  const double diagonal = std::sqrt(0.2 * 0.2 + 0.1 * 0.1 + 0.2 * 0.2);
  EXPECT_GT(state.positions.col(1).minCoeff(), -0.005 * diagonal);
  EXPECT_LT(state.positions.col(1).minCoeff(), 0);  // it is the springs that hold it
}

TEST(ObstacleContact, APaddleSweepingThroughPushesTheBlockWithoutEnteringIt) {
  SimulationOptions options = rubber(0);
  Obstacle paddle;
  paddle.name = "paddle";
  paddle.shape =
      std::make_shared<ClosedSurfaceDistance>(box({-0.05, 0.01, -0.2}, {0, 0.09, 0.4}), "paddle");
  paddle.motion = {{0, {-0.02, 0, 0}, Eigen::Quaterniond::Identity()},
                   {1, {0.48, 0, 0}, Eigen::Quaterniond::Identity()}};  // 0.5 m/s along +x
  options.obstacles = {slab(0.3, 0.3), paddle};
  Simulation sim(oneLevel(block()), 0, options);
  const double x0 = mean(sim.state().positions).x();
  double deepest = 0;
  for (int i = 0; i < 200; ++i) {
    sim.step();
    const Points3 x = sim.state().positions;
    for (Index v = 0; v < x.rows(); ++v) {
      const auto hit = closestPointOf(paddle, sim.time(), x.row(v).transpose(), 1);
      if (hit) deepest = std::max(deepest, -hit->distance);
    }
  }
  EXPECT_GT(mean(sim.state().positions).x() - x0, 0.3);  // pushed along by ~0.5 m/s for ~0.9 s
  EXPECT_LT(deepest, 0.005 * kBlockSize);
}

TEST(ObstacleContact, ARigidMotionOfTheWholeSceneChangesNothing) {
  const double theta = 10 * M_PI / 180;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Vector3d shift(0.3, -1.2, 2.5);
  SimulationOptions options = rubber(theta);
  options.obstacles = {slab(0.5, 0.4)};
  // (Dropped from 2 mm: no node starts exactly touching, where rounding
  // would decide which of the two runs counts it.)
  TetMesh lifted = block();
  lifted.nodes.col(1).array() += 0.002;
  Simulation plain(oneLevel(lifted), 0, options);
  TetMesh moved = lifted;
  for (Index v = 0; v < moved.nodeCount(); ++v)
    moved.nodes.row(v) = (turn * moved.nodes.row(v).transpose() + shift).transpose();
  options.gravity = turn * options.gravity;
  options.obstacles = {slab(0.5, 0.4, {shift, turn, 1})};
  Simulation turned(oneLevel(moved), 0, options);
  for (int i = 0; i < 100; ++i) {
    const StepStats a = plain.step(), b = turned.step();
    ASSERT_EQ(a.contacts, b.contacts) << "step " << i;
  }
  // The same to the solver's tolerance, which the two runs meet in
  // different iterations: 1e-5 of the block's size.
  const SimulationState a = plain.state(), b = turned.state();
  for (Index v = 0; v < a.positions.rows(); ++v)
    EXPECT_NEAR((turn.conjugate() * (b.positions.row(v).transpose() - shift) -
                 a.positions.row(v).transpose())
                    .norm(),
                0, 1e-5 * kBlockSize)
        << v;
  const Eigen::Vector3d fa = plain.contactForces(a).colwise().sum().transpose();
  const Eigen::Vector3d fb = turned.contactForces(b).colwise().sum().transpose();
  EXPECT_NEAR((turn.conjugate() * fb - fa).norm(), 0, 1e-4 * fa.norm());
}

// An obstacle placed anew before a step (the GUI's box widget, while
// paused) acts as one placed there from the start: both runs step alike.
TEST(ObstacleContact, AnObstaclePlacedAnewActsAsOnePlacedThereFromTheStart) {
  SimulationOptions options = rubber(0);
  TetMesh lifted = block();
  lifted.nodes.col(1).array() += 0.002;
  const ObstaclePose raised{{0, 0.001, 0}, Eigen::Quaterniond::Identity(), 1};
  options.obstacles = {slab(0.5, 0.4)};
  Simulation moved(oneLevel(lifted), 0, options);
  moved.setObstaclePlacement(0, raised);
  EXPECT_EQ(moved.options().obstacles[0].placement.translation, raised.translation);
  options.obstacles = {slab(0.5, 0.4, raised)};
  Simulation placed(oneLevel(lifted), 0, options);
  for (int i = 0; i < 40; ++i) {
    const StepStats a = moved.step(), b = placed.step();
    ASSERT_EQ(a.contacts, b.contacts) << "step " << i;
  }
  EXPECT_EQ(moved.state().positions, placed.state().positions);
  EXPECT_GT(moved.contactForces(moved.state()).colwise().sum().norm(), 0);  // it has landed
  EXPECT_THROW(moved.setObstaclePlacement(1, raised), Error);
  EXPECT_THROW(moved.setObstaclePlacement(0, {{0, 0, 0}, Eigen::Quaterniond::Identity(), 0}),
               Error);
}

// A skin 1 cm outside the block's cage on every side: the skin, not the
// cage, rests on the slab (the cage's base stays about 1 cm above it),
// held by contact forces equal to the weight on every step (friction is
// gathered per node, so skin points sharing nodes do not chatter in and
// out of contact); with the cage as the contact points the skin sinks
// 1 cm into the slab instead.
// The block with its base at `base` and a skin 1 cm outside it on every
// side (the surface of a finer grid: four skin vertices to a cage node),
// bound to it.
struct SkinnedBlock {
  MultiLevelTetMesh dataset;
  SurfaceMesh skin;
  SurfaceBinding binding;
};
SkinnedBlock skinnedBlock(double base) {
  TetMesh cage = block();
  cage.nodes.col(1).array() += base;
  SkinnedBlock b{oneLevel(cage), {}, {}};
  TetMesh shell = tetGrid(8, 4, 8, {0.22, 0.12, 0.22});
  shell.nodes.rowwise() += Eigen::RowVector3d(-0.01, base - 0.01, -0.01);
  b.skin = boundarySurface(shell);
  b.binding = bindSurface(b.skin, b.dataset, 0);
  return b;
}

// `body` run for `steps` steps under `options`, its skin colliding: the run
// and each step's contacts.
std::pair<std::unique_ptr<Simulation>, std::vector<int>> runSkinned(
    const SkinnedBlock& body, const SimulationOptions& options, int steps) {
  auto sim = std::make_unique<Simulation>(body.dataset, 0, options);
  sim->setContactSkin(body.skin, body.binding);
  std::vector<int> contacts;
  for (int i = 0; i < steps; ++i) contacts.push_back(sim->step().contacts);
  return {std::move(sim), contacts};
}

TEST(ObstacleContact, TheSkinCollidesThroughItsBinding) {
  const SkinnedBlock body = skinnedBlock(0.012);
  const MultiLevelTetMesh& dataset = body.dataset;
  const SurfaceMesh& skin = body.skin;
  const SurfaceBinding& binding = body.binding;
  std::vector<int> contacts;
  std::vector<double> support;
  const auto settle = [&](ContactPoints points) {
    SimulationOptions options = rubber(0);
    options.material.massDamping = 2;
    options.obstacles = {slab(0.5, 0.4)};
    options.contactPoints = points;
    auto sim = std::make_unique<Simulation>(dataset, 0, options);
    sim->setContactSkin(skin, binding);
    contacts.clear();
    support.clear();
    for (int i = 0; i < 300; ++i) {
      contacts.push_back(sim->step().contacts);
      support.push_back(sim->contactForces(sim->state()).colwise().sum()(1));
    }
    return sim;
  };
  const auto skinLowest = [&](const Simulation& sim) {
    // The skin's corners follow their faces' nodes with the binding's
    // offsets: the lowest is below the cage's lowest node by about 1 cm.
    return sim.state().positions.col(1).minCoeff() - 0.01;
  };
  const auto bySkin = settle(ContactPoints::Skin);
  const double diagonal = std::sqrt(0.22 * 0.22 + 0.12 * 0.12 + 0.22 * 0.22);
  EXPECT_GT(bySkin->state().positions.col(1).minCoeff(), 0.008);  // the cage stays up
  EXPECT_GT(skinLowest(*bySkin), -0.005 * diagonal);
  const double weight = bySkin->nodeMasses().sum() * kStandardGravity;
  // The last 50 steps: the same contacts, the weight held on each.
  for (std::size_t i = 250; i < 300; ++i) {
    EXPECT_EQ(contacts[i], contacts[249]) << "step " << i;
    EXPECT_NEAR(support[i], weight, 0.01 * weight) << "step " << i;
  }
  const auto byCage = settle(ContactPoints::Cage);
  EXPECT_LT(skinLowest(*byCage), -0.008);  // the skin sinks by about its margin
}

// A static obstacle's clearance (points that have moved less than their
// known distance outside it are not looked up) skips no contact: the skin
// dropped onto the slab runs bit for bit as onto the same slab given two
// keyframes at the same pose, which is looked up in full every step.
TEST(ObstacleContact, TheClearanceOfAStaticObstacleSkipsNoContact) {
  const SkinnedBlock body = skinnedBlock(0.03);
  const auto run = [&](bool keyed) {
    SimulationOptions options = rubber(0);
    options.obstacles = {slab(0.5, 0.4)};
    if (keyed) {
      PoseKey start, end;  // (both at the slab's pose)
      end.time = 10;
      options.obstacles[0].motion = {start, end};
    }
    return runSkinned(body, options, 120);
  };
  const auto [cached, cachedContacts] = run(false);
  const auto [full, fullContacts] = run(true);
  EXPECT_EQ(cachedContacts, fullContacts);
  EXPECT_GT(*std::max_element(cachedContacts.begin(), cachedContacts.end()), 0);  // it landed
  EXPECT_EQ(cachedContacts.front(), 0);                                           // (from 3 cm up)
  EXPECT_EQ(cached->state().positions, full->state().positions);
}

// The same block and skin dropped onto a ball (radius 0.15, finely
// tessellated) under its centre comes to rest on it: its deepest skin
// vertex, measured against the exact sphere, less than 0.5% of the
// diagonal inside, the contact forces (springs and friction) equal to the
// weight within 1% and no sideways force left.
TEST(ObstacleContact, ABlockDroppedOntoABallRestsOnItsSkin) {
  const SkinnedBlock body = skinnedBlock(0.02);
  const MultiLevelTetMesh& dataset = body.dataset;
  const SurfaceMesh& skin = body.skin;
  const SurfaceBinding& binding = body.binding;
  const Eigen::Vector3d centre(0.1, -0.15, 0.1);
  constexpr double kRadius = 0.15;
  Obstacle ball;
  ball.name = "ball";
  ball.shape = std::make_shared<ClosedSurfaceDistance>(sphere(centre, kRadius, 64, 128), "ball");
  SimulationOptions options = rubber(0);
  options.material.massDamping = 2;
  options.obstacles = {ball};
  Simulation sim(dataset, 0, options);
  sim.setContactSkin(skin, binding);
  for (int i = 0; i < 400; ++i) sim.step();
  const SimulationState state = sim.state();
  SurfaceDeformer deformer(skin, binding, dataset.nodes);
  Points3 placed;
  deformer.deformPositions(state.positions, placed);
  const double deepest =
      (kRadius - (placed.rowwise() - centre.transpose()).rowwise().norm().array()).maxCoeff();
  const double diagonal = std::sqrt(0.22 * 0.22 + 0.12 * 0.12 + 0.22 * 0.22);
  EXPECT_LT(deepest, 0.005 * diagonal);
  EXPECT_GT(deepest, -0.005 * diagonal);  // it rests on the ball, not beside it
  const double weight = sim.nodeMasses().sum() * kStandardGravity;
  const Eigen::Vector3d support = sim.contactForces(state).colwise().sum().transpose();
  EXPECT_NEAR(support.y(), weight, 0.01 * weight);
  EXPECT_LT(std::hypot(support.x(), support.z()), 0.01 * weight);
}

// The floor is the simplest obstacle: a skinned block dropped onto a floor
// at y = 0 runs as onto a slab whose top is y = 0 with the floor's friction
// (the same contacts every step, the same positions to round-off), and
// rests on its skin (the cage 1 cm up, the weight carried within 1%).
TEST(FloorObstacle, TheFloorActsAsASlabAndTheSkinRestsOnIt) {
  const SkinnedBlock body = skinnedBlock(0.03);
  const auto run = [&](bool floor) {
    SimulationOptions options = rubber(0);
    options.material.massDamping = 2;  // to settle
    if (floor) {
      options.floorHeight = 0;
      options.friction = 0.5;
    } else {
      options.obstacles = {slab(0.5, 0.5)};
    }
    return runSkinned(body, options, 300);
  };
  const auto [onFloor, floorContacts] = run(true);
  const auto [onSlab, slabContacts] = run(false);
  EXPECT_EQ(floorContacts, slabContacts);
  EXPECT_GT(floorContacts.back(), 0);
  EXPECT_LT((onFloor->state().positions - onSlab->state().positions).cwiseAbs().maxCoeff(),
            1e-9 * kBlockSize);
  const SimulationState state = onFloor->state();
  EXPECT_GT(state.positions.col(1).minCoeff(), 0.008);  // the cage stays up: the skin holds it
  const double weight = onFloor->nodeMasses().sum() * kStandardGravity;
  EXPECT_NEAR(onFloor->contactForces(state).colwise().sum()(1), weight, 0.01 * weight);
}

// Coulomb friction on the floor: a block set sliding at v0 on a floor with
// mu stops after v0^2 / (2 mu g) (the floor's friction was once a share of
// the tangential velocity lost per step, which stops it at a distance set
// by the time step instead).
TEST(FloorObstacle, ABlockSetSlidingStopsWhereCoulombSays) {
  SimulationOptions options = rubber(0);
  options.floorHeight = 0;
  options.friction = 0.4;
  Simulation sim(oneLevel(block()), 0, options);
  for (int i = 0; i < 100; ++i) sim.step();  // 0.5 s: the springs carry the weight
  const Eigen::Vector3d start = mean(sim.state().positions);
  Points3 velocities = sim.state().velocities;
  velocities.col(0).array() += 1.0;  // v0 = 1 m/s along x
  sim.setVelocities(velocities);
  for (int i = 0; i < 100; ++i) sim.step();  // 0.5 s: it stops after 0.25 s
  const double slid = mean(sim.state().positions).x() - start.x();
  const double expected = 1.0 / (2 * 0.4 * kStandardGravity);
  EXPECT_NEAR(slid, expected, 0.05 * expected);
  EXPECT_LT(std::abs(mean(sim.state().velocities).x()), 0.01);  // and it has stopped
  std::printf("slid %.4g m, Coulomb's v0^2 / (2 mu g) = %.4g m\n", slid, expected);
}

}  // namespace
}  // namespace tetskin::test
