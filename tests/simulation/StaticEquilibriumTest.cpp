// SPDX-License-Identifier: AGPL-3.0-or-later
// The static solve (Simulation::solveStatic), against answers found
// another way: the cantilever's equilibrium as heavily damped implicit steps
// reach it, its supports carrying its weight, a block resting on the floor
// carried by its contact springs, driven nodes on their targets; a run
// started from the equilibrium stays at rest; a free body under gravity has
// no equilibrium and is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "SimulationBodies.h"

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

}  // namespace
}  // namespace tetskin::test
