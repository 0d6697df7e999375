// SPDX-License-Identifier: AGPL-3.0-or-later
// The units a simulation step composes (modules/simulation/src), each on
// its own: the floor's springs, the fixed and driven nodes'
// rows, the implicit-Euler system over the force models (and a model the
// integrator has never heard of), the node numbering. Known answers on a
// small grid; whole runs are SimulationTest's.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "BodyContact.h"
#include "BodyModels.h"
#include "ImplicitEuler.h"
#include "NodeConstraints.h"
#include "NodeNumbering.h"
#include "ObstacleContact.h"
#include "Shapes.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

using test::tetGrid;
using test::unitTetrahedron;

// The floor is an obstacle (ObstacleContact with floorObstacle): a spring
// h^2 k on the up axis of each node on or below the plane, k depth - h k v
// in its force; nodes above it, however close, get none.
TEST(FloorObstacle, SpringsOnNodesOnOrBelowThePlaneOnly) {
  const Eigen::VectorXd mass = Eigen::VectorXd::Ones(9);
  ObstacleContact floor({floorObstacle({UpAxis::Z, 0.5}, 0.3, 1000.0)}, mass, 1.0, 1.0);
  Eigen::VectorXd x(9), v(9);
  x << 0, 0, 1.0,  // above
      0, 0, 0.5,   // touching
      0, 0, 0.4;   // 0.1 below
  v << 0, 0, -1, 0, 0, -2, 0, 0, -3;
  const double h = 0.01;
  StepSystem system;
  system.diagonal = mass;  // (the springs add to it)
  system.force = Eigen::VectorXd::Zero(9);
  EXPECT_EQ(floor.addForce({x, v, h}, system), 2);
  Eigen::VectorXd springs = Eigen::VectorXd::Zero(9), force = springs;
  springs[5] = springs[8] = h * h * 1000.0;
  force[5] = 0 - h * 1000.0 * -2;
  force[8] = 1000.0 * 0.1 - h * 1000.0 * -3;
  ASSERT_TRUE(system.hasSprings);
  EXPECT_TRUE(system.springs.isApprox(springs));
  EXPECT_TRUE(system.diagonal.isApprox(mass + springs));
  EXPECT_NEAR((system.force - force).norm(), 0, 1e-12);
  // Its force at a state, for reactions: k depth below the plane only.
  Eigen::VectorXd atRest = Eigen::VectorXd::Zero(9);
  floor.addForceAt(x, v, atRest);
  EXPECT_NEAR(atRest[8], 100.0, 1e-12);
  EXPECT_EQ(atRest.sum(), atRest[8]);
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
  const BodyModels body = bodyModels(fem, options);
  ImplicitEuler integrator(options.timeStep, fem.lumpedMass());
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd b;
  const Eigen::VectorXd x = fem.restPositions(), v = Eigen::VectorXd::Zero(x.size());
  EXPECT_EQ(integrator.assemble(body.models, 0, x, v, Eigen::VectorXd::Zero(x.size()), A, b), 0);
  EXPECT_EQ(integrator.springs(), nullptr);  // no floor
  const Eigen::VectorXd dv = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(A).solve(b);
  const Eigen::Vector3d expected = options.timeStep * options.gravity / (1 + 0.02 * 0.5);
  for (Index node = 0; node < fem.nodeCount(); ++node)
    EXPECT_NEAR((dv.segment<3>(3 * node) - expected).norm(), 0, 1e-12) << node;
  Eigen::VectorXd newX, newV;
  integrator.advance(body.models, x, v, dv, newX, newV);
  EXPECT_TRUE(newV.isApprox(dv));
  EXPECT_TRUE((newX - x).isApprox(options.timeStep * dv));
}

TEST(ImplicitEuler, CoarseOperatorsDiscretizeTheSameStep) {
  SimulationOptions options;
  options.timeStep = 0.01;
  options.material.massDamping = 2;
  options.material.stiffnessDamping = 0.1;
  CorotatedFem fem(unitTetrahedron(), options.material);
  const auto coarse = [&] {
    return ImplicitEuler(options.timeStep, fem.lumpedMass())
        .coarseDiscretization(bodyModels(fem, options).models);
  };
  const CoarseDiscretization full = coarse();
  EXPECT_DOUBLE_EQ(full.massScale, 1 + 0.01 * 2);
  EXPECT_DOUBLE_EQ(full.terms.stiffnessScale, 0.01 * 0.1 + 0.01 * 0.01);
  EXPECT_DOUBLE_EQ(full.terms.rotationScale, 0.01 * 0.01);
  options.tangent = Tangent::Warped;
  EXPECT_EQ(coarse().terms.rotationScale, 0);
}

// The sum of the models is the implicit-Euler step written out whole, as
// the integrator computed it before the models existed: A = (1 + h alpha) M
// + (h beta + h^2) K + h^2 K_rot + the floor's h^2 k, b = h (f_el - (beta +
// h) K v - h K_rot v + f_ext + M (g - alpha v)) + h (k depth - h k v).
TEST(ImplicitEuler, TheModelsSumIsTheStepWrittenOut) {
  const TetMesh mesh = tetGrid(3, 2, 2, {1.5, 1, 1});
  SimulationOptions options;
  options.material.massDamping = 0.7;
  options.material.stiffnessDamping = 0.05;
  options.timeStep = 0.01;
  options.floorHeight = 0.2;  // crosses the grid's lowest layer of nodes, moved below
  options.floorStiffness = 5e4;
  CorotatedFem fem(mesh, options.material);
  const BodyModels body = bodyModels(fem, options);
  Eigen::VectorXd x = fem.restPositions(), v(x.size()), external(x.size());
  for (Index i = 0; i < x.size(); ++i) {
    x[i] += 0.03 * std::sin(1.7 * static_cast<double>(i));
    v[i] = 0.4 * std::cos(0.9 * static_cast<double>(i));
    external[i] = 2.0 * std::sin(0.3 * static_cast<double>(i));
  }
  ImplicitEuler integrator(options.timeStep, fem.lumpedMass());
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd b;
  const int contacts = integrator.assemble(body.models, 0, x, v, external, A, b);

  const double h = options.timeStep, alpha = 0.7, beta = 0.05, k = 5e4;
  const Eigen::VectorXd& M = fem.lumpedMass();
  Eigen::VectorXd diagonal = (1 + h * alpha) * M, floorForce = Eigen::VectorXd::Zero(x.size());
  int below = 0;
  for (Index node = 0; node < fem.nodeCount(); ++node) {
    const Index dof = 3 * node + 1;
    if (x[dof] > 0.2) continue;
    ++below;
    diagonal[dof] += h * h * k;
    floorForce[dof] = k * (0.2 - x[dof]) - h * k * v[dof];
  }
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = h * beta + h * h;
  terms.diagonal = &diagonal;
  terms.velocity = &v;
  terms.velocityWeight = beta + h;
  terms.rotationScale = h * h;
  terms.rotationVelocityWeight = h;
  SparseMatrix expectedA = fem.pattern();
  Eigen::VectorXd force;
  fem.update(x, force, expectedA, terms);
  Eigen::VectorXd expectedB(x.size());
  for (Index node = 0; node < fem.nodeCount(); ++node)
    expectedB.segment<3>(3 * node) =
        h * (force.segment<3>(3 * node) + external.segment<3>(3 * node) +
             M.segment<3>(3 * node).cwiseProduct(options.gravity - alpha * v.segment<3>(3 * node)));
  expectedB += h * floorForce;

  EXPECT_GT(below, 0);
  EXPECT_EQ(contacts, below);
  const Eigen::Map<const Eigen::VectorXd> values(A.valuePtr(), A.nonZeros()),
      expectedValues(expectedA.valuePtr(), expectedA.nonZeros());
  EXPECT_LE((values - expectedValues).cwiseAbs().maxCoeff(),
            1e-12 * expectedValues.cwiseAbs().maxCoeff());
  EXPECT_LE((b - expectedB).cwiseAbs().maxCoeff(), 1e-12 * expectedB.cwiseAbs().maxCoeff());
}

// A model the integrator does not know: springs of stiffness c m per node
// towards the rest positions shifted by d. From rest, every node gets the
// same force m (c d + g) and spring c m, so a rigid dv solves the step:
// (m + h^2 c m) dv = h m (c d + g), whatever the elastic stiffness.
class ShiftedAnchors : public ForceModel {
 public:
  ShiftedAnchors(const Eigen::VectorXd& mass, const Eigen::VectorXd& rest, double c,
                 const Eigen::Vector3d& d)
      : mass_(mass), rest_(rest), c_(c), d_(d) {}
  int addForce(const StepState& at, StepSystem& system) override {
    for (Index dof = 0; dof < at.x.size(); ++dof) {
      const double k = c_ * mass_[dof];
      system.addSpring(dof, at.h * at.h * k);
      system.force[dof] += k * (rest_[dof] + d_[dof % 3] - at.x[dof]) - at.h * k * at.v[dof];
    }
    return static_cast<int>(at.x.size() / 3);
  }

 private:
  const Eigen::VectorXd& mass_;
  const Eigen::VectorXd& rest_;
  double c_;
  Eigen::Vector3d d_;
};

TEST(ImplicitEuler, StepsAForceModelItDoesNotKnow) {
  const TetMesh mesh = tetGrid(2, 2, 1, {1, 1, 0.5});
  SimulationOptions options;
  options.material.massDamping = 0;
  options.timeStep = 0.01;
  CorotatedFem fem(mesh, options.material);
  BodyModels body = bodyModels(fem, options);
  const double c = 400;
  const Eigen::Vector3d d(0.01, -0.02, 0.03);
  body.models.push_back(
      std::make_unique<ShiftedAnchors>(fem.lumpedMass(), fem.restPositions(), c, d));
  ImplicitEuler integrator(options.timeStep, fem.lumpedMass());
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd b;
  const Eigen::VectorXd x = fem.restPositions(), v = Eigen::VectorXd::Zero(x.size());
  EXPECT_EQ(integrator.assemble(body.models, 0, x, v, Eigen::VectorXd::Zero(x.size()), A, b),
            mesh.nodeCount());
  ASSERT_NE(integrator.springs(), nullptr);  // what rediscretized coarse levels restrict
  const Eigen::VectorXd dv = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(A).solve(b);
  const double h = options.timeStep;
  const Eigen::Vector3d expected = h * (c * d + options.gravity) / (1 + h * h * c);
  for (Index node = 0; node < fem.nodeCount(); ++node)
    EXPECT_NEAR((dv.segment<3>(3 * node) - expected).norm(), 0, 1e-12) << node;
}

TEST(ForceModels, TheForceAtRestIsTheWeightAndTheEnergiesAreTheirs) {
  const TetMesh mesh = tetGrid(2, 1, 1, {2, 1, 1});
  SimulationOptions options;
  options.material.massDamping = 1;
  CorotatedFem fem(mesh, options.material);
  const BodyModels body = bodyModels(fem, options);
  const Eigen::VectorXd x = fem.restPositions();
  Eigen::VectorXd force = Eigen::VectorXd::Zero(x.size());
  for (const auto& model : body.models)
    model->addForceAt(x, Eigen::VectorXd::Zero(x.size()), force);
  for (Index node = 0; node < fem.nodeCount(); ++node)
    EXPECT_NEAR((force.segment<3>(3 * node) - fem.lumpedMass()[3 * node] * options.gravity).norm(),
                0, 1e-9)
        << node;
  // Moving: damping -alpha M v joins; lifted by 1 m: -m g . (0, 1, 0) each.
  const Eigen::VectorXd v = Eigen::VectorXd::Constant(x.size(), 2.0);
  Eigen::VectorXd moving = Eigen::VectorXd::Zero(x.size());
  for (const auto& model : body.models) model->addForceAt(x, v, moving);
  EXPECT_NEAR((moving - force + 2.0 * fem.lumpedMass()).norm(), 0, 1e-9);
  Eigen::VectorXd lifted = x;
  for (Index node = 0; node < fem.nodeCount(); ++node) lifted[3 * node + 1] += 1;
  Energies e;
  for (const auto& model : body.models) model->addEnergy(lifted, e);
  EXPECT_NEAR(e.elastic, 0, 1e-9);
  EXPECT_NEAR(e.gravitational, fem.lumpedMass().sum() / 3 * -options.gravity.y(), 1e-9);
}

// Letting contacts go takes their share out of the step as assembled: the
// system after updateActiveSet (b, A, the springs' diagonal, the coupling
// springs) is the one a fresh assembly with the contacts left gives, and
// taking them in again gives the first assembly back. Two
// blocks, their skins 1 cm off their cages, 5 mm into each other's shell,
// the second moving away from the first at the top and into it at the
// bottom: some springs end the step pulling, some pushing.
TEST(BodyContact, TheActiveSetTakesContactsOutOfAndIntoTheAssembledStep) {
  const auto block = [](double x) {
    TetMesh cage = tetGrid(2, 2, 2, {0.2, 0.2, 0.2});
    cage.nodes.col(0).array() += x;
    TetMesh shell = tetGrid(4, 4, 4, {0.22, 0.22, 0.22});
    shell.nodes.array() -= 0.01;
    shell.nodes.col(0).array() += x;
    return std::pair{cage, boundarySurface(shell)};
  };
  const auto oneLevel = [](const TetMesh& cage) {
    MultiLevelTetMesh dataset;
    appendLevel(dataset, cage);
    return dataset;
  };
  const auto [cageA, skinA] = block(0);
  const auto [cageB, skinB] = block(0.2 + 0.02 + 0.003);  // skins 3 mm apart
  const SurfaceBinding bindingA = bindSurface(skinA, oneLevel(cageA), 0),
                       bindingB = bindSurface(skinB, oneLevel(cageB), 0);
  const std::vector<BodyParts> parts{{&cageA, &skinA, &bindingA}, {&cageB, &skinB, &bindingB}};
  const BodyUnion bodies = uniteBodies(parts);
  const TetMesh mesh = extractLevel(bodies.mesh, 0);
  SimulationOptions options;
  options.timeStep = 0.01;
  options.gravity.setZero();
  CorotatedFem fem(mesh, options.material);
  BodyModels body = bodyModels(fem, options);
  const double k = 1e4;
  body.models.push_back(std::make_unique<BodyContact>(
      std::make_unique<SurfaceDeformer>(bodies.skin, bodies.binding, mesh.nodes), bodies.skin,
      bodies.binding, bodies.vertexBody, fem.lumpedMass(), *body.constraints, SkinCollisions{},
      0.005, k));
  auto& contact = static_cast<BodyContact&>(*body.models.back());
  const Eigen::VectorXd x = fem.restPositions();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
  for (Index node = cageA.nodeCount(); node < mesh.nodeCount(); ++node)  // B turns about z
    v[3 * node] = 4 * (x[3 * node + 1] - 0.1);
  ImplicitEuler integrator(options.timeStep, fem.lumpedMass());
  SparseMatrix A = fem.pattern();
  Eigen::VectorXd b;
  const int found =
      integrator.assemble(body.models, 0, x, v, Eigen::VectorXd::Zero(x.size()), A, b);
  ASSERT_GT(found, 0);
  Eigen::VectorXd probe(x.size()), coupledAtFirst = Eigen::VectorXd::Zero(x.size());
  for (Index i = 0; i < probe.size(); ++i) probe[i] = std::sin(0.7 * static_cast<double>(i));
  integrator.coupling()->product(probe.data(), coupledAtFirst.data());
  const SparseMatrix firstA = A;
  const Eigen::VectorXd firstB = b, firstSprings = integrator.stepSystem().springs;
  // (The solve of the step without the coupling, enough to say who pulls.)
  const Eigen::VectorXd dv = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(A).solve(b);
  const BodyContact::ActiveSetChange change =
      contact.updateActiveSet(x, v, dv, integrator.stepSystem());
  const int released = change.released;
  ASSERT_EQ(change.taken, 0);
  ASSERT_FALSE(change.reassemble);
  ASSERT_GT(released, 0);
  ASSERT_LT(released, found);
  const Eigen::VectorXd releasedB = b;
  const SparseMatrix releasedA = A;
  const Eigen::VectorXd springs = integrator.stepSystem().springs;
  Eigen::VectorXd coupled = Eigen::VectorXd::Zero(x.size());
  integrator.coupling()->product(probe.data(), coupled.data());

  // Against the step assembled from scratch with the contacts kept.
  ImplicitEuler again(options.timeStep, fem.lumpedMass());
  SparseMatrix againA = fem.pattern();
  Eigen::VectorXd againB;
  contact.keepNextStep();
  EXPECT_EQ(again.assemble(body.models, 0, x, v, Eigen::VectorXd::Zero(x.size()), againA, againB),
            found - released);
  const Eigen::Map<const Eigen::VectorXd> values(releasedA.valuePtr(), releasedA.nonZeros()),
      expected(againA.valuePtr(), againA.nonZeros());
  EXPECT_LE((values - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_LE((releasedB - againB).cwiseAbs().maxCoeff(), 1e-12 * againB.cwiseAbs().maxCoeff());
  EXPECT_LE((springs - again.stepSystem().springs).cwiseAbs().maxCoeff(),
            1e-12 * springs.maxCoeff());
  Eigen::VectorXd coupledAgain = Eigen::VectorXd::Zero(x.size());
  again.coupling()->product(probe.data(), coupledAgain.data());
  EXPECT_LE((coupled - coupledAgain).cwiseAbs().maxCoeff(), 1e-12 * coupled.cwiseAbs().maxCoeff());

  // And back in: at the end velocity zero (dv = -v) every contact pushes,
  // so those let go are taken in again (and no path crosses a skin), and
  // the step is the first assembly's again.
  const BodyContact::ActiveSetChange back =
      contact.updateActiveSet(x, v, -v, integrator.stepSystem());
  EXPECT_EQ(back.taken, released);
  EXPECT_EQ(back.released, 0);
  EXPECT_EQ(back.crossed, 0);
  const Eigen::Map<const Eigen::VectorXd> backValues(A.valuePtr(), A.nonZeros()),
      firstValues(firstA.valuePtr(), firstA.nonZeros());
  EXPECT_LE((backValues - firstValues).cwiseAbs().maxCoeff(),
            1e-12 * firstValues.cwiseAbs().maxCoeff());
  EXPECT_LE((b - firstB).cwiseAbs().maxCoeff(), 1e-12 * firstB.cwiseAbs().maxCoeff());
  EXPECT_LE((integrator.stepSystem().springs - firstSprings).cwiseAbs().maxCoeff(),
            1e-12 * firstSprings.maxCoeff());
  Eigen::VectorXd coupledBack = Eigen::VectorXd::Zero(x.size());
  integrator.coupling()->product(probe.data(), coupledBack.data());
  EXPECT_LE((coupledBack - coupledAtFirst).cwiseAbs().maxCoeff(),
            1e-12 * coupledAtFirst.cwiseAbs().maxCoeff());
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
