// SPDX-License-Identifier: AGPL-3.0-or-later
// Skins meeting skins (BodyContact): two bodies meeting head-on keep their
// momentum and bounce apart, bodies apart and a body at rest with
// self-contact on find no contact, a U-shaped body whose upper prong
// is pushed down onto its lower one keeps its skin free of
// self-intersections (checked by an exact triangle-triangle test), which
// without self-contact it does not, and a stack of three settles on the
// floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Shapes.h"
#include "SimulationBodies.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/spatial/Aabb.h"
#include "tetskin/spatial/ClosedSurfaceDistance.h"
#include "tetskin/spatial/TriangleIntersection.h"

namespace tetskin::test {
namespace {

// A body: its cage, and a skin (the boundary of a finer grid 1 cm larger
// all round) bound to it.
struct SkinnedBody {
  TetMesh cage;
  SurfaceMesh skin;
  SurfaceBinding binding;
};
SkinnedBody skinnedBlock(const Eigen::Vector3d& corner) {
  SkinnedBody b;
  b.cage = tetGrid(4, 2, 4, {0.2, 0.1, 0.2});
  b.cage.nodes.rowwise() += corner.transpose();
  TetMesh shell = tetGrid(8, 4, 8, {0.22, 0.12, 0.22});
  shell.nodes.rowwise() += (corner - Eigen::Vector3d::Constant(0.01)).transpose();
  b.skin = boundarySurface(shell);
  b.binding = bindSurface(b.skin, oneLevel(b.cage), 0);
  return b;
}

BodyUnion unite(const std::vector<SkinnedBody>& bodies) {
  std::vector<BodyParts> parts;
  for (const SkinnedBody& b : bodies) parts.push_back({&b.cage, &b.skin, &b.binding});
  return uniteBodies(parts);
}

SimulationOptions rubberInSpace() {
  SimulationOptions options;
  options.material.youngsModulus = 2e5;
  options.material.poissonRatio = 0.3;
  options.material.density = 1000;
  options.material.massDamping = 0;  // (it would take momentum out)
  options.material.stiffnessDamping = 0.01;
  options.timeStep = 1.0 / 200;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-10;
  options.gravity.setZero();
  return options;
}

Eigen::Vector3d momentum(const Simulation& sim, const SimulationState& state, Index first,
                         Index count) {
  const Eigen::VectorXd mass = sim.nodeMasses();
  return (state.velocities.middleRows(first, count).array().colwise() *
          mass.segment(first, count).array())
      .colwise()
      .sum()
      .transpose();
}

// The first `n` nodes at `first` m/s along x, the rest at `second`.
void setAlongX(Simulation& sim, Index n, double first, double second) {
  Points3 velocities = Points3::Zero(sim.state().positions.rows(), 3);
  velocities.topRows(n).col(0).setConstant(first);
  velocities.bottomRows(n).col(0).setConstant(second);
  sim.setVelocities(velocities);
}

// Two equal blocks, 8 cm apart (skin to skin) along x, meet head-on at
// 1.5 and -0.5 m/s: the total momentum stays what it was (within 1% of
// it: only the solver's tolerance moves it), the skins' contact forces
// act while they touch, and after it the blocks fly apart, the one that
// came faster now the slower.
TEST(BodyContact, TwoBodiesMeetingHeadOnKeepTheirMomentumAndSeparate) {
  const BodyUnion bodies = unite({skinnedBlock({0, 0, 0}), skinnedBlock({0.3, 0, 0})});
  Simulation sim(bodies.mesh, 0, rubberInSpace());
  sim.setContactSkin(bodies.skin, bodies.binding, bodies.vertexBody);
  EXPECT_GT(sim.skinThickness(), 0);
  const Index n = bodies.bodies[1].firstNode;
  setAlongX(sim, n, 1.5, -0.5);
  const Eigen::Vector3d start = momentum(sim, sim.state(), 0, 2 * n);
  int touching = 0, firstContact = -1;
  double largestDrift = 0;
  for (int i = 0; i < 80; ++i) {
    const int contacts = sim.step().contacts;
    if (contacts > 0) {
      ++touching;
      if (firstContact < 0) firstContact = i;
    }
    largestDrift = std::max(largestDrift, (momentum(sim, sim.state(), 0, 2 * n) - start).norm());
  }
  std::printf("contact from step %d for %d steps; momentum drift at most %.3g of %.3g\n",
              firstContact, touching, largestDrift, start.norm());
  EXPECT_GT(firstContact, 2);  // 8 cm at 2 m/s: 8 steps, less the thickness's
  EXPECT_GE(touching, 2);
  EXPECT_LT(largestDrift, 0.01 * start.norm());
  const SimulationState end = sim.state();
  const double a = momentum(sim, end, 0, n).x(), b = momentum(sim, end, n, n).x();
  std::printf("momenta after the impact: %.3f and %.3f kg m/s\n", a, b);
  EXPECT_LT(a, b);  // the bounce: the first block is now the slower
  const double gap =
      end.positions.bottomRows(n).col(0).minCoeff() - end.positions.topRows(n).col(0).maxCoeff();
  EXPECT_GT(gap, 0.1);  // apart again, farther than they started (0.1 between the cages)
}

// The same blocks at 3 and -3 m/s with a shell of 5 mm: they close 3 cm
// in a step, six shells, so a skin vertex goes from outside the other's
// shell to behind it by more than the shell in one step, where no
// proximity search finds it. Its path does cross the other skin: the
// step's continuous detection makes it a contact, the step is solved
// again with it, and the blocks bounce apart (without it they pass into
// each other: the test fails).
TEST(BodyContact, BodiesFasterThanTheShellPerStepStillMeet) {
  const BodyUnion bodies = unite({skinnedBlock({0, 0, 0}), skinnedBlock({0.3, 0, 0})});
  SimulationOptions options = rubberInSpace();
  options.skinCollisions.thickness = 0.005;
  Simulation sim(bodies.mesh, 0, options);
  sim.setContactSkin(bodies.skin, bodies.binding, bodies.vertexBody);
  const Index n = bodies.bodies[1].firstNode;
  setAlongX(sim, n, 3, -3);
  const Eigen::Vector3d start = momentum(sim, sim.state(), 0, 2 * n);
  double closest = 1;  // the least gap between the cages along x
  for (int i = 0; i < 40; ++i) {
    sim.step();
    const Points3& x = sim.state().positions;
    closest = std::min(closest, x.bottomRows(n).col(0).minCoeff() - x.topRows(n).col(0).maxCoeff());
  }
  const SimulationState end = sim.state();
  const double a = momentum(sim, end, 0, n).x(), b = momentum(sim, end, n, n).x();
  std::printf("momenta after the impact: %.3f and %.3f kg m/s; the cages came within %.4f m\n", a,
              b, closest);
  EXPECT_LT((momentum(sim, end, 0, 2 * n) - start).norm(), 0.01 * std::abs(a));
  EXPECT_LT(a, 0);  // bounced back
  EXPECT_GT(b, 0);
  // The skins are 1 cm off the cages: no skin went into the other by more
  // than its shell, the cages stayed 2 cm less 5 mm apart (without the
  // continuous detection they pass into each other: -6.4 cm).
  EXPECT_GT(closest, 0.015);
}

// Bodies apart, and one body at rest with self-contact on: no contact
// (the neighbourhood of each skin vertex is not a contact).
TEST(BodyContact, BodiesApartAndABodyAtRestFindNone) {
  const BodyUnion apart = unite({skinnedBlock({0, 0, 0}), skinnedBlock({0.3, 0, 0})});
  Simulation two(apart.mesh, 0, rubberInSpace());
  two.setContactSkin(apart.skin, apart.binding, apart.vertexBody);
  EXPECT_EQ(two.step().contacts, 0);
  SimulationOptions options = rubberInSpace();
  options.skinCollisions.self = true;
  const BodyUnion one = unite({skinnedBlock({0, 0, 0})});
  Simulation alone(one.mesh, 0, options);
  alone.setContactSkin(one.skin, one.binding);
  EXPECT_GT(alone.skinThickness(), 0);
  EXPECT_EQ(alone.step().contacts, 0);
  EXPECT_LT((alone.state().positions - one.mesh.nodes).cwiseAbs().maxCoeff(), 1e-15);
  // Without self-contact a single body has no skin contact at all.
  Simulation plain(one.mesh, 0, rubberInSpace());
  plain.setContactSkin(one.skin, one.binding);
  EXPECT_EQ(plain.skinThickness(), 0);
}

// The skins' coefficients are checked as an obstacle's, and thickness
// too, before a step: each refused with its value.
TEST(BodyContact, BadSkinCoefficientsAreRefused) {
  const BodyUnion one = unite({skinnedBlock({0, 0, 0})});
  const auto refused = [&](const auto& edit, const std::string& what) {
    SimulationOptions options = rubberInSpace();
    edit(options.skinCollisions);
    try {
      Simulation sim(one.mesh, 0, options);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused([](SkinCollisions& s) { s.thickness = -1; },
          "the skins' contact thickness must be finite and >= 0 (0: automatic), got -1");
  refused([](SkinCollisions& s) { s.stiffness = std::nan(""); },
          "the skins' contact: the stiffness must be finite and >= 0");
  refused([](SkinCollisions& s) { s.kineticFriction = 0.6; },
          "the skins' contact: friction must satisfy 0 <= kinetic <= static, got static 0.5 and "
          "kinetic 0.6");
}

// A U lying on its side: a base (x < 0.1) with two prongs along x, 5 cm
// apart, its skin the cage's own boundary.
TetMesh uShape() {
  TetMesh grid = tetGrid(12, 5, 2, {0.6, 0.25, 0.1});
  std::vector<int> kept;
  for (Index e = 0; e < grid.elementCount(); ++e) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += grid.nodes.row(grid.elements(e, k)).transpose() / 4;
    if (!(centroid.y() > 0.1 && centroid.y() < 0.15 && centroid.x() > 0.1))
      kept.push_back(static_cast<int>(e));
  }
  TetMesh u;
  u.nodes = grid.nodes;
  u.elements.resize(static_cast<Index>(kept.size()), 4);
  for (std::size_t i = 0; i < kept.size(); ++i)
    u.elements.row(static_cast<Index>(i)) = grid.elements.row(kept[i]);
  removeUnreferencedNodes(u);
  return u;
}

// Pairs of skin triangles that intersect (other than along what they
// share), by the exact test.
int selfIntersections(const SurfaceMesh& skin, const Points3& positions) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(skin.triangleCount()));
  for (Index t = 0; t < skin.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      boxes[static_cast<std::size_t>(t)].extend(
          positions.row(skin.triangles(t, k)).transpose().eval());
  int count = 0;
  for (Index s = 0; s < skin.triangleCount(); ++s)
    for (Index t = s + 1; t < skin.triangleCount(); ++t) {
      if (!boxes[static_cast<std::size_t>(s)].overlaps(boxes[static_cast<std::size_t>(t)]))
        continue;
      Eigen::Vector3d p[3], q[3];
      int pid[3], qid[3];
      for (int k = 0; k < 3; ++k) {
        pid[k] = skin.triangles(s, k);
        qid[k] = skin.triangles(t, k);
        p[k] = positions.row(pid[k]).transpose();
        q[k] = positions.row(qid[k]).transpose();
      }
      if (trianglesIntersect(p, pid, q, qid)) ++count;
    }
  return count;
}

// The U's base and lower prong held, its upper prong's tip pushed down by
// 8 N (without contact it would bend down about 0.2 m, through the lower
// prong): with self-contact its skin rests on the lower prong's, and no
// two of its triangles intersect at any frame; without, they do.
TEST(BodyContact, AFoldedBodyKeepsItsSkinFreeOfSelfIntersections) {
  const TetMesh u = uShape();
  const MultiLevelTetMesh dataset = oneLevel(u);
  const SurfaceMesh skin = boundarySurface(u);
  const SurfaceBinding binding = bindSurface(skin, dataset, 0);
  ASSERT_EQ(selfIntersections(skin, skin.positions), 0);
  std::vector<int> held, tip;
  for (Index i = 0; i < u.nodeCount(); ++i) {
    if (u.nodes(i, 0) <= 0.1 + 1e-9 || u.nodes(i, 1) <= 0.1 + 1e-9)
      held.push_back(static_cast<int>(i));
    if (u.nodes(i, 0) >= 0.6 - 1e-9 && u.nodes(i, 1) >= 0.15 - 1e-9)
      tip.push_back(static_cast<int>(i));
  }
  const auto run = [&](bool selfContact) {
    SimulationOptions options = rubberInSpace();
    options.material.massDamping = 5;
    options.skinCollisions.self = selfContact;
    options.skinCollisions.thickness = 0.01;
    Simulation sim(dataset, 0, options);
    sim.setContactSkin(skin, binding);
    sim.setFixedNodes(held);
    Points3 loads = Points3::Zero(u.nodeCount(), 3);
    for (const int node : tip) loads(node, 1) = -8.0 / static_cast<double>(tip.size());
    sim.setExternalForces(loads);
    SurfaceDeformer deformer(skin, binding, u.nodes);
    int worst = 0;
    Points3 placed;
    double lowestTip = 1;
    for (int i = 1; i <= 200; ++i) {
      sim.step();
      if (i % 10 != 0) continue;
      const SimulationState state = sim.state();
      deformer.deformPositions(state.positions, placed);
      worst = std::max(worst, selfIntersections(skin, placed));
      for (const int node : tip) lowestTip = std::min(lowestTip, state.positions(node, 1));
    }
    return std::pair{worst, lowestTip};
  };
  const auto [with, tipWith] = run(true);
  const auto [without, tipWithout] = run(false);
  std::printf(
      "intersecting triangle pairs: %d with self-contact, %d without; the tip's lowest "
      "node at %.3f and %.3f m\n",
      with, without, tipWith, tipWithout);
  EXPECT_GT(without, 0);            // the push folds it through itself ...
  EXPECT_LT(tipWithout, 0.1);       // (its tip below the lower prong's top)
  EXPECT_EQ(with, 0);               // ... but for the self-contact
  EXPECT_GT(tipWith, 0.15 - 0.05);  // (it came down onto the lower prong, not through it)
}

// Three blocks stacked square on the floor, 1 cm apart skin to skin (each
// skin the shell of a finer grid, 1 cm off its cage), the skins' contact a
// 5 mm shell, settle under gravity: no skin goes into the body below or
// above it by 0.5% of its diagonal (the deepest depth by the exact signed
// distance to that body's closed skin), the floor carries the stack's
// weight to 1% (averaged over the last 50 steps), and each block stays on
// the one below. Without the skins' contact they fall into each other.
// (Friction corrects velocities after the solve: blocks stacked 2 cm aside
// creep off the rounded edges; doc/dev/contact.md.)
TEST(BodyContact, AStackOfThreeSettlesOnTheFloor) {
  std::vector<SkinnedBody> blocks;
  for (int k = 0; k < 3; ++k)  // skin k spans y in [0.01 + 0.13 k, 0.13 + 0.13 k]
    blocks.push_back(skinnedBlock({0, 0.02 + 0.13 * k, 0}));
  const BodyUnion stack = unite(blocks);
  constexpr int kSteps = 300, kAveraged = 50;
  const auto settle = [&](bool contact) {
    SimulationOptions options = rubberInSpace();
    options.gravity = Eigen::Vector3d(0, -kStandardGravity, 0);
    options.material.massDamping = 4;
    options.floorHeight = 0;
    options.timeStep = 0.01;
    options.tolerance = 1e-8;
    options.skinCollisions.thickness = 0.005;
    Simulation sim(stack.mesh, 0, options);
    // Without contact: one body's skin (no skin meets another).
    const std::vector<int> bodies =
        contact ? stack.vertexBody : std::vector<int>(stack.vertexBody.size(), 0);
    sim.setContactSkin(stack.skin, stack.binding, bodies);
    double carried = 0;
    for (int i = 0; i < kSteps; ++i) {
      sim.step();
      if (i >= kSteps - kAveraged) carried += sim.contactForces(sim.state()).col(1).sum();
    }
    return std::pair{sim.state(), carried / kAveraged};
  };
  const auto deepest = [&](const SimulationState& state) {
    SurfaceDeformer deformer(stack.skin, stack.binding, stack.mesh.nodes);
    Points3 skin;
    deformer.deformPositions(state.positions, skin);
    double depth = -1;  // the deepest any skin vertex lies in a neighbour, m
    for (int k = 0; k < 3; ++k) {
      const BodyRange& range = stack.bodies[static_cast<std::size_t>(k)];
      SurfaceMesh placed = bodyPart(stack.skin, range);
      placed.positions = skin.middleRows(range.firstVertex, range.vertexCount);
      const ClosedSurfaceDistance body(placed, "body " + std::to_string(k));
      for (Index v = 0; v < skin.rows(); ++v)
        if (std::abs(stack.vertexBody[static_cast<std::size_t>(v)] - k) == 1)
          depth = std::max(depth, -body.closest(skin.row(v).transpose())->distance);
    }
    return depth;
  };
  const auto [state, carried] = settle(true);
  const double weight =
      Simulation(stack.mesh, 0, rubberInSpace()).nodeMasses().sum() * kStandardGravity;
  const double diagonal = Eigen::Vector3d(0.22, 0.12, 0.22).norm();
  const double depth = deepest(state);
  const double speed = state.velocities.rowwise().norm().maxCoeff();
  std::printf(
      "the stack settled: the floor carries %.4f N of %.4f N, the deepest skin vertex %.2e m "
      "in its neighbour (%.3f%% of the diagonal), the fastest node %.2e m/s\n",
      carried, weight, depth, 100 * depth / diagonal, speed);
  EXPECT_NEAR(carried, weight, 0.01 * weight);
  EXPECT_LT(depth, 0.005 * diagonal);
  EXPECT_LT(speed, 0.05);
  // Still a stack: each block on the one below, where it was put.
  for (int k = 1; k < 3; ++k) {
    const BodyRange& below = stack.bodies[static_cast<std::size_t>(k - 1)];
    const BodyRange& above = stack.bodies[static_cast<std::size_t>(k)];
    const double top =
        state.positions.middleRows(below.firstNode, below.nodeCount).col(1).maxCoeff();
    const double bottom =
        state.positions.middleRows(above.firstNode, above.nodeCount).col(1).minCoeff();
    const double shift =
        state.positions.middleRows(above.firstNode, above.nodeCount).col(0).mean() -
        stack.mesh.nodes.middleRows(above.firstNode, above.nodeCount).col(0).mean();
    std::printf("block %d: %.4f m above the one below, moved %.4f m along x\n", k, bottom - top,
                shift);
    // (Cage to cage: the two skins' 1 cm offsets and at most the shell.)
    EXPECT_GT(bottom - top, 0.02);
    EXPECT_LT(bottom - top, 0.026);
    EXPECT_LT(std::abs(shift), 0.005);
  }
  // Without: the blocks in each other, each one's cage down on the floor.
  const SimulationState fallen = settle(false).first;
  const double sunk =
      fallen.positions.middleRows(stack.bodies[2].firstNode, stack.bodies[2].nodeCount)
          .col(1)
          .minCoeff();
  std::printf("without the skins' contact the top block's cage is down at %.3f m\n", sunk);
  EXPECT_LT(sunk, 0.02);
}

}  // namespace
}  // namespace tetskin::test
