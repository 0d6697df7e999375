// SPDX-License-Identifier: AGPL-3.0-or-later
// Whole simulation runs: the energies: undamped never rising, damped decaying, gravity measured
// from the rest shape.
#include "SimulationBodies.h"

namespace tetskin {
namespace {

using namespace test;

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

}  // namespace
}  // namespace tetskin
