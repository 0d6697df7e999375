// SPDX-License-Identifier: AGPL-3.0-or-later
// The units a simulation step composes (modules/simulation/src), each on
// its own: the floor's springs and projection, the fixed and driven nodes'
// rows, the implicit-Euler system, the node numbering. Known answers on a
// small grid; whole runs are SimulationTest's.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "FloorContact.h"
#include "ImplicitEuler.h"
#include "NodeConstraints.h"
#include "NodeNumbering.h"
#include "Shapes.h"
#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

using test::tetGrid;
using test::unitTetrahedron;

TEST(FloorContact, SpringsOnNodesOnOrBelowThePlaneOnly) {
  FloorContact floor({UpAxis::Z, 0.5}, 1000.0, 0.3);
  Eigen::VectorXd x(9), v(9);
  x << 0, 0, 1.0,  // above
      0, 0, 0.5,   // touching
      0, 0, 0.4;   // 0.1 below
  v << 0, 0, -1, 0, 0, -2, 0, 0, -3;
  const double h = 0.01;
  EXPECT_EQ(floor.linearize(x, v, h), 2);
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(9), force = diagonal;
  diagonal[5] = diagonal[8] = h * h * 1000.0;
  force[5] = 0 - h * 1000.0 * -2;
  force[8] = 1000.0 * 0.1 - h * 1000.0 * -3;
  EXPECT_TRUE(floor.diagonal().isApprox(diagonal));
  EXPECT_NEAR((floor.force() - force).norm(), 0, 1e-12);
}

TEST(FloorContact, ProjectsNodesBelowOntoThePlaneWithFriction) {
  FloorContact floor({UpAxis::Y, 0.0}, 1.0, 0.25);
  Eigen::VectorXd x(6), v(6);
  x << 1, -0.2, 2, 1, 0.3, 2;
  v << 4, -5, 8, 4, -5, 8;
  floor.project(x, v);
  Eigen::VectorXd x1(6), v1(6);
  x1 << 1, 0, 2, 1, 0.3, 2;  // the first on the plane, the second left as it was
  v1 << 3, 0, 6, 4, -5, 8;   // no velocity into the floor, tangential 3/4 of it
  EXPECT_EQ(x, x1);
  EXPECT_EQ(v, v1);
  // Moving away from the floor keeps its speed.
  x << 0, -1, 0, 0, 1, 0;
  v << 0, 2, 0, 0, 2, 0;
  floor.project(x, v);
  EXPECT_EQ(v[1], 2);
}

TEST(NodeConstraints, StopsFixedNodesAndDrivesTargetsToTheirPositions) {
  const TetMesh mesh = tetGrid(2, 1, 1, {2, 1, 1});
  CorotatedFem fem(mesh, ElasticMaterial{});
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd force;
  CorotatedFem::SystemTerms terms;
  const Eigen::VectorXd mass = fem.lumpedMass();
  terms.diagonal = &mass;
  fem.update(fem.restPositions(), force, A, terms);
  NodeConstraints constraints(fem.pattern());
  std::vector<char> fixed(static_cast<std::size_t>(mesh.nodeCount()), 0);
  fixed[0] = fixed[1] = 1;
  constraints.setFixed(fixed);
  EXPECT_TRUE(constraints.isFixed(0));
  EXPECT_FALSE(constraints.isFixed(2));
  const Eigen::Vector3d target(0.1, 0.2, 0.3);
  Points3 targets(1, 3);
  targets.row(0) = target.transpose();
  constraints.setTargets({1}, targets);
  const Eigen::VectorXd x = fem.restPositions();
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(x.size(), 0.5);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(x.size());
  const double h = 0.1;
  constraints.impose(A, b, x, v, h);
  const Eigen::VectorXd dv = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(A).solve(b);
  EXPECT_NEAR((dv.segment<3>(0) + v.segment<3>(0)).norm(), 0, 1e-12);  // stopped
  // The driven node reaches its target at the end of the step.
  EXPECT_NEAR((x.segment<3>(3) + h * (v.segment<3>(3) + dv.segment<3>(3)) - target).norm(), 0,
              1e-12);
  Eigen::VectorXd end = x;
  constraints.placeOnTargets(end);
  EXPECT_EQ(Eigen::Vector3d(end.segment<3>(3)), target);
  EXPECT_EQ(end.segment<3>(0), x.segment<3>(0));
  // New fixed nodes drop the targets.
  constraints.setFixed(fixed);
  end = x;
  constraints.placeOnTargets(end);
  EXPECT_EQ(end, x);
}

TEST(ImplicitEuler, AFreeBodyAtRestFallsUniformly) {
  // At rest the elastic forces vanish and a rigid translation costs no
  // strain: the solve's dv is h g / (1 + h alpha) at every node.
  const TetMesh mesh = tetGrid(2, 2, 2, {1, 1, 1});
  SimulationOptions options;
  options.material.massDamping = 0.5;
  options.timeStep = 0.02;
  CorotatedFem fem(mesh, options.material);
  ImplicitEuler integrator(options, fem);
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd b;
  const Eigen::VectorXd x = fem.restPositions(), v = Eigen::VectorXd::Zero(x.size());
  integrator.assemble(fem, x, v, Eigen::VectorXd::Zero(x.size()), nullptr, nullptr, A, b);
  const Eigen::VectorXd dv = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(A).solve(b);
  const Eigen::Vector3d expected = options.timeStep * options.gravity / (1 + 0.02 * 0.5);
  for (Index node = 0; node < fem.nodeCount(); ++node)
    EXPECT_NEAR((dv.segment<3>(3 * node) - expected).norm(), 0, 1e-12) << node;
  Eigen::VectorXd newX, newV;
  integrator.advance(x, v, dv, newX, newV);
  EXPECT_TRUE(newV.isApprox(dv));
  EXPECT_TRUE((newX - x).isApprox(options.timeStep * dv));
}

TEST(ImplicitEuler, CoarseOperatorsDiscretizeTheSameStep) {
  SimulationOptions options;
  options.timeStep = 0.01;
  options.material.massDamping = 2;
  options.material.stiffnessDamping = 0.1;
  const CorotatedFem fem(unitTetrahedron(), options.material);
  const CoarseDiscretization full = ImplicitEuler(options, fem).coarseDiscretization();
  EXPECT_DOUBLE_EQ(full.massScale, 1 + 0.01 * 2);
  EXPECT_DOUBLE_EQ(full.terms.stiffnessScale, 0.01 * 0.1 + 0.01 * 0.01);
  EXPECT_DOUBLE_EQ(full.terms.rotationScale, 0.01 * 0.01);
  options.tangent = Tangent::Warped;
  EXPECT_EQ(ImplicitEuler(options, fem).coarseDiscretization().terms.rotationScale, 0);
}

TEST(NodeNumbering, RoundTripsAndKeepsTheElements) {
  const TetMesh mesh = tetGrid(3, 2, 2, {3, 2, 2});
  const NodeNumbering numbering(mesh, "grid");
  Points3 values = Points3::Random(mesh.nodeCount(), 3);
  EXPECT_EQ(numbering.toOutside(numbering.toInternal(values)), values);
  const TetMesh internal = numbering.renumbered(mesh);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(internal.nodes.row(internal.elements(e, k)), mesh.nodes.row(mesh.elements(e, k)));
  for (Index i = 0; i < mesh.nodeCount(); ++i)
    EXPECT_EQ(numbering.internal(numbering.outside(i)), i);
  // An inverted element is refused, named as the caller says.
  TetMesh inverted = mesh;
  std::swap(inverted.elements(0, 0), inverted.elements(0, 1));
  try {
    NodeNumbering bad(inverted, "bunny.json: level 0");
    FAIL() << "an inverted element was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bunny.json: level 0"), std::string::npos) << e.what();
  }
  EXPECT_EQ(levelName("", 2), "level 2");
  EXPECT_EQ(levelName("a.json", 0), "a.json: level 0");
}

}  // namespace
}  // namespace tetskin
