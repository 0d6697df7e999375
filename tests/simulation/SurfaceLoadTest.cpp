// SPDX-License-Identifier: AGPL-3.0-or-later
// Pressure and traction on boundary faces (SurfaceLoad.h, Simulation::
// setSurfaceLoads), against answers known without them: a load's total is
// its value times the loaded area, a pressure turns with the surface, the
// forces are minus the gradient of the potential; a free cube under a
// pressure is under a hydrostatic stress, a free bar pulled by end
// tractions under a uniaxial one; a clamp carries a cantilever's end
// traction, and the load's work is twice the elastic energy (Clapeyron).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "BoundarySelection.h"
#include "SimulationBodies.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin::test {
namespace {

Eigen::VectorXd stacked(const Points3& points) {
  return points.reshaped<Eigen::RowMajor>();
}

Eigen::Vector3d total(const Eigen::VectorXd& forces) {
  return forces.reshaped(3, forces.size() / 3).rowwise().sum();
}

// The boundary faces whose corners' positions all satisfy `keep`, as a
// load with no value yet.
template <class Keep>
SurfaceLoad facesWhere(const TetMesh& mesh, Keep keep) {
  SurfaceLoad load;
  load.faces = boundaryFacesWhere(mesh, [&](Index node) { return keep(mesh.nodes.row(node)); });
  return load;
}

SurfaceLoad wholeBoundary(const TetMesh& mesh) {
  return facesWhere(mesh, [](const auto&) { return true; });
}

const Eigen::Vector3d kBox{1.5, 2, 2.5};

TEST(SurfaceLoad, TotalsArePressureAndTractionTimesTheArea) {
  const TetMesh block = tetGrid(3, 4, 5, kBox);
  const Eigen::VectorXd rest = stacked(block.nodes);
  const double p = 1234.5;
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  double sides = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int end = 0; end < 2; ++end) {
      const double at = end * kBox[axis];
      SurfaceLoad side =
          facesWhere(block, [&](const auto& node) { return std::abs(node(axis) - at) < 1e-12; });
      side.pressure = p;
      const double area = kBox.prod() / kBox[axis];
      EXPECT_NEAR(loadedArea(side, rest), area, 1e-13 * area);
      Eigen::VectorXd forces = Eigen::VectorXd::Zero(rest.size());
      addSurfaceLoadForces(side, rest, rest, 1.0, forces);
      Eigen::Vector3d expected = Eigen::Vector3d::Zero();
      expected[axis] = end == 0 ? p * area : -p * area;  // into the body
      EXPECT_LE((total(forces) - expected).norm(), 1e-12 * p * area)
          << "axis " << axis << ", end " << end;
      net += total(forces);
      sides += total(forces).norm();
    }
  const double area = 2 * (kBox.x() * kBox.y() + kBox.y() * kBox.z() + kBox.z() * kBox.x());
  EXPECT_NEAR(sides, p * area, 1e-12 * p * area);
  EXPECT_LE(net.norm(), 1e-12 * p * area);

  // The whole closed boundary: the pressure sums to nothing, a traction to
  // itself times the area.
  SurfaceLoad closed = wholeBoundary(block);
  closed.pressure = p;
  closed.traction = {3, -2, 1};
  EXPECT_NEAR(loadedArea(closed, rest), area, 1e-12 * area);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(rest.size());
  addSurfaceLoadForces(closed, rest, rest, 1.0, forces);
  EXPECT_LE((total(forces) - closed.traction * area).norm(), 1e-12 * p * area);
  // The factor scales both.
  Eigen::VectorXd scaled = Eigen::VectorXd::Zero(rest.size());
  addSurfaceLoadForces(closed, rest, rest, 0.25, scaled);
  EXPECT_LE((scaled - 0.25 * forces).cwiseAbs().maxCoeff(), 1e-12 * forces.cwiseAbs().maxCoeff());
}

TEST(SurfaceLoad, PressureTurnsWithTheSurfaceAndATractionDoesNot) {
  const TetMesh block = tetGrid(2, 2, 3, kBox);
  const Eigen::VectorXd rest = stacked(block.nodes);
  SurfaceLoad load = facesWhere(block, [](const auto& node) { return node(1) > 2 - 1e-12; });
  load.pressure = 50;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(3, -1, 2);
  Eigen::VectorXd turned(rest.size());
  for (Index v = 0; v < block.nodeCount(); ++v)
    turned.segment<3>(3 * v) = R * rest.segment<3>(3 * v) + shift;
  Eigen::VectorXd atRest = Eigen::VectorXd::Zero(rest.size()), now = atRest;
  addSurfaceLoadForces(load, rest, rest, 1.0, atRest);
  addSurfaceLoadForces(load, rest, turned, 1.0, now);
  for (Index v = 0; v < block.nodeCount(); ++v)
    EXPECT_LE((now.segment<3>(3 * v) - R * atRest.segment<3>(3 * v)).norm(), 1e-12 * atRest.norm());
  load.pressure = 0;
  load.traction = {0, 10, 0};
  Eigen::VectorXd dead = Eigen::VectorXd::Zero(rest.size()), deadTurned = dead;
  addSurfaceLoadForces(load, rest, rest, 1.0, dead);
  addSurfaceLoadForces(load, rest, turned, 1.0, deadTurned);
  EXPECT_EQ(dead, deadTurned);
}

// Central differences of the potential along a random direction against
// minus the forces.
double potentialSlopeError(const SurfaceLoad& load, const Eigen::VectorXd& rest,
                           const Eigen::VectorXd& x) {
  const Eigen::VectorXd direction = Eigen::VectorXd::Random(x.size());
  const double h = 1e-6;
  const double slope = (surfaceLoadEnergy(load, rest, x + h * direction, 2.0) -
                        surfaceLoadEnergy(load, rest, x - h * direction, 2.0)) /
                       (2 * h);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(x.size());
  addSurfaceLoadForces(load, rest, x, 2.0, forces);
  return std::abs(slope + forces.dot(direction)) / (forces.norm() * direction.norm());
}

TEST(SurfaceLoad, TheForcesAreMinusThePotentialsGradient) {
  const TetMesh block = tetGrid(2, 3, 2, kBox);
  const Eigen::VectorXd rest = stacked(block.nodes);
  std::srand(7);
  const Eigen::VectorXd moved = rest + 0.05 * Eigen::VectorXd::Random(rest.size());
  SurfaceLoad closed = wholeBoundary(block);  // a pressure is conservative on a closed surface
  closed.pressure = 300;
  EXPECT_LT(potentialSlopeError(closed, rest, moved), 1e-7);
  SurfaceLoad patch = facesWhere(block, [](const auto& node) { return node(0) < 1e-12; });
  patch.traction = {1, -4, 2};
  EXPECT_LT(potentialSlopeError(patch, rest, moved), 1e-7);
  // At rest there is no potential.
  EXPECT_EQ(surfaceLoadEnergy(closed, rest, rest, 1.0), 0);
}

TEST(SurfaceLoad, ProblemsAreNamed) {
  SurfaceLoad load;
  EXPECT_EQ(surfaceLoadProblem(load, 8), "it has no face");
  load.faces.resize(1, 3);
  load.faces << 0, 1, 8;
  EXPECT_EQ(surfaceLoadProblem(load, 8), "face 0 names node 8, which the level (8 nodes) lacks");
  load.faces << 0, 1, 1;
  EXPECT_EQ(surfaceLoadProblem(load, 8), "face 0 names a node twice");
  load.faces << 0, 1, 2;
  load.pressure = std::nan("");
  EXPECT_EQ(surfaceLoadProblem(load, 8), "its pressure must be finite, got nan");
  load.pressure = 1;
  EXPECT_EQ(surfaceLoadProblem(load, 8), std::nullopt);
  Simulation sim(oneLevel(tetGrid(1, 1, 1, {1, 1, 1})), 0, SimulationOptions{});
  load.faces << 0, 1, 9;
  EXPECT_EQ(errorText([&] { sim.setSurfaceLoads({load}); }),
            "surface load 0: face 0 names node 9, which the level (8 nodes) lacks");
}

SimulationOptions staticOptions() {
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 1e6;
  options.material.poissonRatio = 0.3;
  options.material.density = 1;
  options.material.stiffnessDamping = 0;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-12;
  return options;
}

TEST(SurfaceLoad, AFreeCubeUnderAPressureIsUnderAHydrostaticStress) {
  const TetMesh cube = tetGrid(4, 4, 4, {1, 1, 1});
  const SimulationOptions options = staticOptions();
  Simulation sim(oneLevel(cube), 0, options);
  SurfaceLoad load = wholeBoundary(cube);
  const double p = 1e-3 * options.material.youngsModulus;
  load.pressure = p;
  sim.setSurfaceLoads({load});
  const StaticStats stats = sim.solveStatic();
  std::printf("pressed cube: %d Newton iterations, residual %.3g N (load %.3g N)\n",
              stats.iterations, stats.residual, stats.load);
  ASSERT_TRUE(stats.converged);
  const SimulationState state = sim.state();
  // Bulk modulus K = E / (3 (1 - 2 nu)): the volume shrinks by p / K.
  const double K = options.material.youngsModulus / (3 * (1 - 2 * options.material.poissonRatio));
  const double shrink = 1 - meshVolume({state.positions, cube.elements}) / meshVolume(cube);
  EXPECT_NEAR(shrink, p / K, 0.01 * p / K);
  // Every element: sigma = -p I (to the area's change, p / K of it, as the
  // pressure acts on the shrunk faces).
  const FrameFields fields = sim.frameFields(state);
  ASSERT_EQ(fields.stress.rows(), cube.elementCount());
  SymmetricTensors hydrostatic = SymmetricTensors::Zero(cube.elementCount(), 6);
  hydrostatic.leftCols(3).setConstant(-p);
  const double off = (fields.stress - hydrostatic).cwiseAbs().maxCoeff();
  std::printf("pressed cube: volume down %.6g (p / K %.6g), stress off -p I by %.3g p at most\n",
              shrink, p / K, off / p);
  EXPECT_LE(off, 3 * p / K * p);
  // The load's nodal forces are the frame's external forces.
  EXPECT_LE((fields.externalForces - sim.surfaceLoadForces(state)).cwiseAbs().maxCoeff(), 0);
  EXPECT_GT(fields.externalForces.cwiseAbs().maxCoeff(), 0);
}

TEST(SurfaceLoad, EndTractionsPullAFreeBarIntoAUniaxialStress) {
  const TetMesh bar = pulledBar();  // 6 x 1 x 1
  Simulation sim(oneLevel(bar), 0, staticOptions());
  const double t = 1e3;
  SurfaceLoad left = facesWhere(bar, [](const auto& node) { return node(0) < 1e-12; });
  SurfaceLoad right = facesWhere(bar, [](const auto& node) { return node(0) > 6 - 1e-12; });
  left.traction = {-t, 0, 0};
  right.traction = {t, 0, 0};
  sim.setSurfaceLoads({left, right});
  ASSERT_TRUE(sim.solveStatic().converged);
  const FrameFields fields = sim.frameFields(sim.state());
  // Linear tetrahedra hold a constant stress exactly (the patch test): a
  // dead load's stress is t along x and nothing else, to the solve.
  SymmetricTensors uniaxial = SymmetricTensors::Zero(bar.elementCount(), 6);
  uniaxial.col(0).setConstant(t);
  const double off = (fields.stress - uniaxial).cwiseAbs().maxCoeff();
  // Stretched by t / E.
  const double length = fields.positions.col(0).maxCoeff() - fields.positions.col(0).minCoeff();
  std::printf("pulled bar: stress off t e_x e_x by %.3g t at most, strain %.9g (t / E %.9g)\n",
              off / t, length / 6 - 1, t / 1e6);
  EXPECT_LE(off, 1e-6 * t);
  EXPECT_NEAR(length / 6 - 1, t / 1e6, 1e-6 * t / 1e6);
}

TEST(SurfaceLoad, AClampCarriesACantileversEndTractionAndTheLoadWorksTwiceTheStrain) {
  const TetMesh beam = tetGrid(20, 2, 2, {kBeamLength, kBeamHeight, kBeamWidth});
  SimulationOptions options = staticOptions();
  options.material.poissonRatio = 0;
  Simulation sim(oneLevel(beam), 0, options);
  sim.setFixedNodes(nodesWithXBelow(beam, 1e-9));
  SurfaceLoad end =
      facesWhere(beam, [](const auto& node) { return node(0) > kBeamLength - 1e-12; });
  const double t = 1;  // Pa on the 1 m^2 end: a tip deflection of ~4e-5 of the length
  end.traction = {0, -t, 0};
  sim.setSurfaceLoads({end});
  ASSERT_TRUE(sim.solveStatic().converged);
  const SimulationState state = sim.state();
  const Eigen::Vector3d reaction = sim.supportReaction(state);
  EXPECT_NEAR(reaction.y(), t * kBeamHeight * kBeamWidth, 1e-8 * t);
  EXPECT_NEAR(reaction.x(), 0, 1e-8 * t);
  // Clapeyron: at a linear equilibrium the load's potential is minus
  // twice the strain energy.
  const Energies e = sim.energies();
  std::printf("end traction: elastic %.6g J, load potential %.6g J\n", e.elastic, e.load);
  EXPECT_LT(e.load, 0);
  EXPECT_NEAR(e.elastic, -e.load / 2, 1e-4 * e.elastic);
  // The frame's external forces are the load's; half the factor (as a
  // load curve sets it), half the forces.
  const Points3 full = sim.surfaceLoadForces(state);
  EXPECT_EQ(sim.frameFields(state).externalForces, full);
  sim.setSurfaceLoadFactor(0.5);
  EXPECT_LE((sim.surfaceLoadForces(state) * 2 - full).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(SurfaceLoad, TheScenarioScalesThemByTheLoadCurveAndLetsGo) {
  const TetMesh beam = tetGrid(10, 1, 1, {kBeamLength, kBeamHeight, kBeamWidth});
  ScenarioParameters p;
  p.baseShare = 0;
  p.fixedNodes = nodesWithXBelow(beam, 1e-9);
  SurfaceLoad end =
      facesWhere(beam, [](const auto& node) { return node(0) > kBeamLength - 1e-12; });
  end.traction = {0, -2, 0};
  p.surfaceLoads = {end};
  p.loadCurve = LoadCurve({{0, 0}, {1, 1}});
  p.loadSeconds = 2;
  Simulation sim(oneLevel(beam), 0, staticOptions());
  const auto sag = makeScenario("sag", p);
  sag->setUp(sim);
  const auto totalNow = [&] {
    return Eigen::Vector3d(sim.surfaceLoadForces(sim.state()).colwise().sum().transpose());
  };
  sag->beforeStep(sim, 0.25);
  EXPECT_NEAR(totalNow().y(), -0.5, 1e-12);
  sag->beforeStep(sim, 1.5);
  EXPECT_NEAR(totalNow().y(), -2, 1e-12);
  sag->beforeStep(sim, 2.5);
  EXPECT_EQ(totalNow().norm(), 0);
}

}  // namespace
}  // namespace tetskin::test
