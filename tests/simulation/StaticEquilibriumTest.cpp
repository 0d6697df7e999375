// SPDX-License-Identifier: AGPL-3.0-or-later
// The static solve (Simulation::solveStatic), against answers found
// another way: the cantilever's equilibrium as heavily damped implicit steps
// reach it, its supports carrying its weight, a block resting on the floor
// carried by its contact springs, driven nodes on their targets; a run
// started from the equilibrium stays at rest; a free body under gravity has
// no equilibrium and is refused.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "BoundarySelection.h"
#include "SimulationBodies.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin::test {
namespace {

TetMesh shortCantilever() {
  return tetGrid(40, 4, 4, {kBeamLength, kBeamHeight, kBeamWidth});
}

TEST(StaticSolve, ReachesTheCantileversSettledEquilibrium) {
  const TetMesh beam = shortCantilever();
  const SimulationOptions options = staticBeamOptions();
  Simulation marched(oneLevel(beam), 0, options);
  marched.setFixedNodes(nodesWithXBelow(beam, 1e-9));
  const double settled = settledTipDeflection(marched, nullptr);

  Simulation sim(oneLevel(beam), 0, options);
  sim.setFixedNodes(nodesWithXBelow(beam, 1e-9));
  const StaticStats stats = sim.solveStatic();
  std::printf(
      "static solve: %d Newton iterations, %d cg iterations, residual %.3g N (load %.3g N)\n",
      stats.iterations, stats.linearIterations, stats.residual, stats.load);
  EXPECT_TRUE(stats.converged);
  EXPECT_LE(stats.residual, std::max(1e-8 * stats.load, stats.floor));
  EXPECT_LT(stats.floor, 1e-7 * stats.load);  // (the beam's floor is far below its load)
  EXPECT_LT(stats.iterations, 20);
  const SimulationState state = sim.state();
  const double tip = tipDeflection(beam, state.positions);
  EXPECT_NEAR(tip, settled, 1e-6 * settled);
  EXPECT_EQ(state.velocities.cwiseAbs().maxCoeff(), 0);
  // The clamp carries the whole weight.
  const double weight = sim.nodeMasses().sum() * kStandardGravity;
  EXPECT_NEAR(sim.supportReaction(state).y(), weight, 1e-8 * weight);
}

TEST(StaticSolve, ARunStartedFromTheEquilibriumStaysAtRest) {
  const TetMesh beam = shortCantilever();
  SimulationOptions options = staticBeamOptions();
  options.material.massDamping = 0;  // nothing to hide a drift
  options.timeStep = 0.01;
  Simulation sim(oneLevel(beam), 0, options);
  sim.setFixedNodes(nodesWithXBelow(beam, 1e-9));
  ASSERT_TRUE(sim.solveStatic().converged);
  double fastest = 0;
  for (int i = 0; i < 100; ++i) {  // 1 s
    sim.step();
    fastest = std::max(fastest, sim.state().velocities.rowwise().norm().maxCoeff());
  }
  std::printf("fastest node over 1 s from the equilibrium: %.3g m/s\n", fastest);
  EXPECT_LT(fastest, 1e-6 * kBeamLength);
}

TEST(StaticSolve, ABlockRestsOnTheFloorOnItsContactSprings) {
  SimulationOptions options;
  options.material.youngsModulus = 2e5;
  options.material.density = 1000;
  options.floorHeight = 0;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-10;
  const TetMesh block = tetGrid(4, 2, 4, {0.2, 0.1, 0.2});
  Simulation sim(oneLevel(block), 0, options);
  const StaticStats stats = sim.solveStatic();
  EXPECT_TRUE(stats.converged) << stats.residual << " N after " << stats.iterations;
  const SimulationState state = sim.state();
  const double weight = sim.nodeMasses().sum() * kStandardGravity;
  EXPECT_NEAR(sim.contactForces(state).colwise().sum()(1), weight, 1e-8 * weight);
  EXPECT_LT(state.positions.col(1).minCoeff(), 0);  // on its springs, a little below
  EXPECT_GT(state.positions.col(1).minCoeff(), -0.005 * 0.3);
  // Nothing pushes it sideways: it bulges (Poisson) but has not slid
  // along the floor, which holds it by the regularization alone.
  const Eigen::RowVector3d shift = state.positions.colwise().mean() - block.nodes.colwise().mean();
  EXPECT_LT(std::hypot(shift.x(), shift.z()), 1e-4 * 0.2);
}

TEST(StaticSolve, PutsDrivenNodesOnTheirTargets) {
  const TetMesh beam = shortCantilever();
  SimulationOptions options = staticBeamOptions();
  options.gravity.setZero();
  Simulation sim(oneLevel(beam), 0, options);
  std::vector<int> held = nodesWithXBelow(beam, 1e-9);
  std::vector<int> driven;
  for (Index v : freeEnd(beam)) driven.push_back(static_cast<int>(v));
  held.insert(held.end(), driven.begin(), driven.end());
  sim.setFixedNodes(held);
  Points3 targets(static_cast<Index>(driven.size()), 3);
  for (std::size_t k = 0; k < driven.size(); ++k)
    targets.row(static_cast<Index>(k)) = beam.nodes.row(driven[k]) + Eigen::RowVector3d(0, 0.2, 0);
  sim.setKinematicTargets(driven, targets);
  const StaticStats stats = sim.solveStatic();
  EXPECT_TRUE(stats.converged);
  const SimulationState state = sim.state();
  for (std::size_t k = 0; k < driven.size(); ++k)
    EXPECT_EQ(state.positions.row(driven[k]), targets.row(static_cast<Index>(k)));
  // Bent by its ends alone, it is in balance: what the clamp carries, the
  // driven end carries back.
  const Points3 reactions = sim.reactionForces(state);
  Eigen::RowVector3d clamp = Eigen::RowVector3d::Zero();
  for (int v : nodesWithXBelow(beam, 1e-9)) clamp += reactions.row(v);
  EXPECT_GT(clamp.norm(), 0);
  EXPECT_LT(sim.supportReaction(state).norm(), 1e-6 * clamp.norm());
}

TEST(StaticSolve, RefusesAFreeBodyUnderGravity) {
  SimulationOptions options;
  Simulation sim(oneLevel(tetGrid(2, 2, 2, {1, 1, 1})), 0, options);
  EXPECT_NE(errorText([&] { sim.solveStatic(); })
                .find("there is no static equilibrium: the body is free (no held node, floor "
                      "or obstacle) under a net load of 0,-"),
            std::string::npos);
}

// Rollers (Simulation::setHeldAxes): a block whose base slides on its
// plane, pressed by a traction on its top, is under a uniaxial stress and
// free to bulge: every element at -t along y alone, the width grown by
// nu t / E, the base's reactions along y alone carrying the load. Held
// whole instead, the base would hold the bulge back.
TEST(StaticSolve, ABlockOnRollersIsUnderAUniaxialStress) {
  const TetMesh block = tetGrid(2, 4, 2, {1, 2, 1});
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 1e6;
  options.material.poissonRatio = 0.3;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-12;
  Simulation sim(oneLevel(block), 0, options);
  std::vector<int> held;
  std::vector<std::array<bool, 3>> axes;
  for (Index v = 0; v < block.nodeCount(); ++v) {
    if (block.nodes(v, 1) > 1e-9) continue;
    // The base slides; its corner at the origin is held along x and z
    // too, and the one at (1, 0, 0) along z, against a rigid drift and turn.
    const bool origin = block.nodes.row(v).norm() < 1e-9;
    const bool corner = (block.nodes.row(v) - Eigen::RowVector3d(1, 0, 0)).norm() < 1e-9;
    held.push_back(static_cast<int>(v));
    axes.push_back({origin, true, origin || corner});
  }
  sim.setHeldAxes(held, axes);
  const double t = 1e3;
  SurfaceLoad top;
  top.faces = boundaryFacesWhere(block, [&](Index v) { return block.nodes(v, 1) > 2 - 1e-9; });
  top.traction = {0, -t, 0};
  sim.setSurfaceLoads({top});
  ASSERT_TRUE(sim.solveStatic().converged);
  const SimulationState state = sim.state();
  const FrameFields fields = sim.frameFields(state);
  for (Index e = 0; e < block.elementCount(); ++e)
    for (int c = 0; c < 6; ++c)
      ASSERT_NEAR(fields.stress(e, c), c == 1 ? -t : 0.0, 1e-6 * t) << "element " << e;
  const double width = state.positions.col(0).maxCoeff() - state.positions.col(0).minCoeff();
  EXPECT_NEAR(width - 1, 0.3 * t / 1e6, 1e-6 * 0.3 * t / 1e6);
  const Eigen::Vector3d reaction = sim.supportReaction(state);
  EXPECT_NEAR(reaction.y(), t * 1.0, 1e-8 * t);
  EXPECT_NEAR(reaction.x(), 0, 1e-8 * t);
  EXPECT_NEAR(reaction.z(), 0, 1e-8 * t);
  // Every base node is a prescribed one; a node held along no axis is
  // refused.
  EXPECT_EQ(sim.conditions().prescribedNodes.size(), held.size());
  EXPECT_EQ(errorText([&] {
              sim.setHeldAxes({0}, {{false, false, false}});
            }),
            "held node 0 is held along no axis");
}

}  // namespace
}  // namespace tetskin::test
