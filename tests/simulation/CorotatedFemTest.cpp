// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <random>
#include <span>
#include <string>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {
namespace {

ElasticMaterial material() {
  ElasticMaterial m;
  m.youngsModulus = 1000;
  m.poissonRatio = 0.3;
  return m;
}

// The rest positions mapped by A, node by node.
Eigen::VectorXd linearlyMapped(const CorotatedFem& fem, const Eigen::Matrix3d& A) {
  Eigen::VectorXd x(fem.dofCount());
  for (Index v = 0; v < fem.nodeCount(); ++v)
    x.segment<3>(3 * v) = A * fem.restPositions().segment<3>(3 * v);
  return x;
}

TEST(CorotatedFem, ElementStiffnessIsSymmetricPsdWithSixRigidModes) {
  TetMesh t = test::unitTetrahedron();
  t.nodes.row(3) << 0.2, 0.3, 1.1;
  const CorotatedFem fem(t, material());
  const Eigen::Matrix<double, 12, 12> K = fem.elementStiffness(0);
  EXPECT_TRUE(K.isApprox(K.transpose(), 1e-12));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eig(K);
  const auto values = eig.eigenvalues();
  const double scale = values.maxCoeff();
  int zeros = 0;
  for (int i = 0; i < 12; ++i) {
    EXPECT_GT(values[i], -1e-10 * scale);
    zeros += std::abs(values[i]) < 1e-10 * scale ? 1 : 0;
  }
  EXPECT_EQ(zeros, 6);
  // Translations are in the null space: block rows sum to zero.
  for (int i = 0; i < 4; ++i) {
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    for (int j = 0; j < 4; ++j) sum += K.block<3, 3>(3 * i, 3 * j);
    EXPECT_LT(sum.norm(), 1e-10 * scale);
  }
}

TEST(CorotatedFem, RotationOfPolarDecomposition) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  Eigen::Matrix3d S;
  S << 1.2, 0.1, 0, 0.1, 0.9, 0.05, 0, 0.05, 1.1;
  EXPECT_TRUE(CorotatedFem::rotation(R * S).isApprox(R, 1e-10));
  // Inverted element: F has a negative determinant; R stays a proper rotation.
  Eigen::Matrix3d inverted = R * S;
  inverted.col(1) *= -0.3;
  const Eigen::Matrix3d Ri = CorotatedFem::rotation(inverted);
  EXPECT_NEAR(Ri.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((Ri.transpose() * Ri).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
}

TEST(CorotatedFem, FastRotationEqualsTheSvdRotationColdAndWarm) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int inverted = 0;
  for (int i = 0; i < 2000; ++i) {
    Eigen::Matrix3d F;
    for (int k = 0; k < 9; ++k) F(k / 3, k % 3) = u(random);
    F += (i % 2 ? 1.5 : 0.2) * Eigen::Matrix3d::Identity();  // near and far from a rotation
    inverted += F.determinant() < 0;
    const Eigen::Matrix3d reference = CorotatedFem::rotation(F);
    Eigen::Quaterniond cold = Eigen::Quaterniond::Identity();
    const Eigen::Matrix3d fast = CorotatedFem::rotation(F, cold);
    EXPECT_TRUE(fast.isApprox(reference, 1e-8)) << "F =\n" << F;
    EXPECT_NEAR(fast.determinant(), 1.0, 1e-12);
    // Warm start from a nearby rotation, as from the last time step.
    Eigen::Quaterniond warm(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()) *
                            Eigen::Quaterniond(reference));
    EXPECT_TRUE(CorotatedFem::rotation(F, warm).isApprox(reference, 1e-8));
  }
  EXPECT_GT(inverted, 100);  // inverted elements were among them
}

TEST(CorotatedFem, RigidMotionProducesNoElasticForce) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, 1, -0.2).normalized()).toRotationMatrix();
  Eigen::VectorXd x(fem.dofCount()), f;
  for (Index v = 0; v < fem.nodeCount(); ++v)
    x.segment<3>(3 * v) = R * fem.restPositions().segment<3>(3 * v) + Eigen::Vector3d(5, -2, 1);
  SparseMatrix K = fem.pattern();
  fem.update(x, f, K);
  EXPECT_LT(f.norm(), 1e-9);
  // Round-off only: a 1% strain of this block stores about 0.6.
  EXPECT_LT(fem.elasticEnergy(x), 1e-9);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    EXPECT_TRUE(fem.elementRotation(e).isApprox(R, 1e-10));
}

// A stretch s along x, turned: every element's rotated-frame strain is
// diag(s, 0, 0), whose equivalent strain is 2/3 s and whose stress's von
// Mises value is 2 mu s; a rigid motion has neither.
TEST(CorotatedFem, ElementMeasuresOfATurnedStretchAreKnown) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  const ElasticMaterial m = material();
  CorotatedFem fem(mesh, m);
  const double s = 0.02, mu = m.youngsModulus / (2 * (1 + m.poissonRatio));
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -0.4, 0.5).normalized()).toRotationMatrix();
  const CorotatedFem::ElementMeasures stretched =
      fem.elementMeasures(linearlyMapped(fem, Q * Eigen::Vector3d(1 + s, 1, 1).asDiagonal()));
  const CorotatedFem::ElementMeasures rigid = fem.elementMeasures(linearlyMapped(fem, Q));
  ASSERT_EQ(stretched.vonMisesStress.size(), mesh.elementCount());
  ASSERT_EQ(stretched.equivalentStrain.size(), mesh.elementCount());
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    EXPECT_NEAR(stretched.equivalentStrain[e], 2.0 / 3.0 * s, 1e-12) << e;
    EXPECT_NEAR(stretched.vonMisesStress[e], 2 * mu * s, 1e-9 * mu) << e;
    EXPECT_LT(rigid.equivalentStrain[e], 1e-12) << e;
    EXPECT_LT(rigid.vonMisesStress[e], 1e-9 * mu) << e;
  }
}

TEST(CorotatedFem, ForcesRotateWithTheBody) {
  const TetMesh mesh = test::tetGrid(2, 2, 2, {1, 1, 1});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.05);
  Eigen::VectorXd x = fem.restPositions();
  for (Index i = 0; i < x.size(); ++i) x[i] += noise(rng);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::VectorXd Qx(x.size()), f, fq;
  for (Index v = 0; v < fem.nodeCount(); ++v) Qx.segment<3>(3 * v) = Q * x.segment<3>(3 * v);
  SparseMatrix K = fem.pattern();
  fem.update(x, f, K);
  fem.update(Qx, fq, K);
  for (Index v = 0; v < fem.nodeCount(); ++v)
    EXPECT_TRUE(fq.segment<3>(3 * v).isApprox(Q * f.segment<3>(3 * v), 1e-9));
}

TEST(CorotatedFem, ForceIsTheNegativeEnergyGradient) {
  const TetMesh mesh = test::tetGrid(2, 1, 1, {2, 1, 1});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0, 0.08);
  Eigen::VectorXd x = fem.restPositions();
  for (Index i = 0; i < x.size(); ++i) x[i] += noise(rng);
  Eigen::VectorXd f;
  SparseMatrix K = fem.pattern();
  fem.update(x, f, K);
  const double h = 1e-6;
  for (Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    const double gradient = (fem.elasticEnergy(plus) - fem.elasticEnergy(minus)) / (2 * h);
    EXPECT_NEAR(-gradient, f[i], 1e-5 * (1 + std::abs(f[i]))) << "dof " << i;
  }
}

// The assembled stiffness is the sum over elements of R_e K_e R_e^T, and the
// force -R_e K_e (R_e^T x_e - X_e), with K_e the rest stiffness and R_e the
// rotations of this state: a dense reference assembly from the public
// per-element pieces.
TEST(CorotatedFem, AssemblyEqualsTheSumOfRotatedElementMatrices) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.1);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  Eigen::VectorXd x = linearlyMapped(fem, Q);
  for (Index i = 0; i < x.size(); ++i) x[i] += noise(rng);
  Eigen::VectorXd f;
  SparseMatrix K = fem.pattern();
  fem.update(x, f, K);
  Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(fem.dofCount(), fem.dofCount());
  Eigen::VectorXd referenceForce = Eigen::VectorXd::Zero(fem.dofCount());
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    const Eigen::Matrix3d& R = fem.elementRotation(e);
    Eigen::Matrix<double, 12, 12> rotation = Eigen::Matrix<double, 12, 12>::Zero();
    Eigen::Matrix<double, 12, 1> xe, Xe;
    for (int k = 0; k < 4; ++k) {
      rotation.block<3, 3>(3 * k, 3 * k) = R;
      xe.segment<3>(3 * k) = x.segment<3>(3 * mesh.elements(e, k));
      Xe.segment<3>(3 * k) = fem.restPositions().segment<3>(3 * mesh.elements(e, k));
    }
    const Eigen::Matrix<double, 12, 12> Ke = fem.elementStiffness(e);
    const Eigen::Matrix<double, 12, 12> rotated = rotation * Ke * rotation.transpose();
    const Eigen::Matrix<double, 12, 1> fe = -rotation * Ke * (rotation.transpose() * xe - Xe);
    for (int i = 0; i < 4; ++i) {
      const Index ni = mesh.elements(e, i);
      referenceForce.segment<3>(3 * ni) += fe.segment<3>(3 * i);
      for (int j = 0; j < 4; ++j)
        reference.block<3, 3>(3 * ni, 3 * mesh.elements(e, j)) += rotated.block<3, 3>(3 * i, 3 * j);
    }
  }
  const Eigen::MatrixXd assembled(K);
  EXPECT_LT((assembled - reference).norm(), 1e-10 * reference.norm());
  EXPECT_LT((f - referenceForce).norm(), 1e-10 * referenceForce.norm());
  EXPECT_GT(referenceForce.norm(), 1.0);  // the state is really deformed
}

// The element pass runs four elements at a time in vector lanes (AVX2 where
// the CPU has it) and hands lanes that need more than small Newton steps to
// the scalar rotation. Both kernels, cold (large rotations: the scalar
// fallback) and warm (small changes: the vector steps), on a mesh whose
// element count leaves the last group of four part empty, give the SVD's
// rotation of every element and the same forces and matrix to rounding.
TEST(CorotatedFem, VectorAndBaselineKernelsAgreeWithTheSvdRotations) {
  const TetMesh mesh = test::tetGrid(3, 1, 1, {3, 1, 1});
  ASSERT_NE(mesh.elementCount() % 4, 0);
  CorotatedFem fastest(mesh, material()), baseline(mesh, material());
  baseline.setKernel(SimdKernel::Baseline);
  std::mt19937 rng(17);
  std::normal_distribution<double> noise(0, 1);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.2, 1, 0.4).normalized()).toRotationMatrix();
  Eigen::VectorXd x = linearlyMapped(fastest, Q), v(fastest.dofCount()), D(fastest.dofCount());
  for (Index i = 0; i < x.size(); ++i) {
    x[i] += 0.1 * noise(rng);
    v[i] = noise(rng);
    D[i] = 2 + std::abs(noise(rng));
  }
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 0.01;
  terms.diagonal = &D;
  terms.velocity = &v;
  terms.velocityWeight = 0.2;
  terms.rotationScale = 0.005;
  terms.rotationVelocityWeight = 0.1;
  for (const double change : {0.0, 1e-3, 1e-5, 1e-8}) {  // cold, then warm steps
    for (Index i = 0; i < x.size(); ++i) x[i] += change * noise(rng);
    Eigen::VectorXd f, fBaseline;
    SparseMatrix A = fastest.pattern(), ABaseline = baseline.pattern();
    fastest.update(x, f, A, terms);
    baseline.update(x, fBaseline, ABaseline, terms);
    EXPECT_LT((f - fBaseline).norm(), 1e-12 * f.norm()) << "change " << change;
    EXPECT_LT((Eigen::MatrixXd(A) - Eigen::MatrixXd(ABaseline)).norm(),
              1e-12 * Eigen::MatrixXd(A).norm())
        << "change " << change;
    for (Index e = 0; e < mesh.elementCount(); ++e) {
      Eigen::Matrix3d deformed, rest;
      for (int k = 0; k < 3; ++k) {
        deformed.col(k) =
            x.segment<3>(3 * mesh.elements(e, k + 1)) - x.segment<3>(3 * mesh.elements(e, 0));
        rest.col(k) =
            (mesh.nodes.row(mesh.elements(e, k + 1)) - mesh.nodes.row(mesh.elements(e, 0)))
                .transpose();
      }
      const Eigen::Matrix3d svd = CorotatedFem::rotation(deformed * rest.inverse());
      EXPECT_TRUE(fastest.elementRotation(e).isApprox(svd, 1e-10)) << "element " << e;
      EXPECT_TRUE(baseline.elementRotation(e).isApprox(svd, 1e-10)) << "element " << e;
    }
  }
}

// The element pass's matrix alone: s K + q K_rot (no diagonal, no velocity).
Eigen::MatrixXd tangent(CorotatedFem& fem, const Eigen::VectorXd& x, double s, double q) {
  Eigen::VectorXd f;
  SparseMatrix A = fem.pattern();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = s;
  terms.rotationScale = q;
  fem.update(x, f, A, terms);
  return Eigen::MatrixXd(A);
}

// The exact tangent applied to d, -df/dx d, by central differences of the
// force.
Eigen::VectorXd forceDerivative(CorotatedFem& fem, const Eigen::VectorXd& x,
                                const Eigen::VectorXd& d) {
  constexpr double h = 1e-6;
  Eigen::VectorXd fPlus, fMinus;
  SparseMatrix unused = fem.pattern();
  fem.update(x + h * d, fPlus, unused);
  fem.update(x - h * d, fMinus, unused);
  return -(fPlus - fMinus) / (2 * h);
}

// The implicit step's terms assembled in the element pass: s K + q K_rot + D
// equals the same built from the plain stiffness and the rotation term alone
// (its compressive modes dropped); f_el - w K v - u K_rot v the same with
// the exact K_rot (none dropped: K_rot v = K_T v - K v, the exact tangent
// K_T by differences of the force). The state compresses some elements, so
// that the two K_rot differ.
TEST(CorotatedFem, SystemTermsEqualScaledStiffnessPlusDiagonalAndDampedForce) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.1);
  Eigen::VectorXd x = fem.restPositions(), v(fem.dofCount()), D(fem.dofCount());
  for (Index i = 0; i < x.size(); ++i) {
    x[i] += noise(rng);
    v[i] = noise(rng);
    D[i] = 1 + std::abs(noise(rng));
  }
  Eigen::VectorXd f, fTerms;
  SparseMatrix K = fem.pattern(), A = fem.pattern();
  fem.update(x, f, K);
  const Eigen::MatrixXd rotationTerm = tangent(fem, x, 0, 1);
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 0.3;
  terms.diagonal = &D;
  terms.velocity = &v;
  terms.velocityWeight = 0.7;
  terms.rotationScale = 0.2;
  terms.rotationVelocityWeight = 0.4;
  fem.update(x, fTerms, A, terms);
  const Eigen::MatrixXd expected =
      0.3 * Eigen::MatrixXd(K) + 0.2 * rotationTerm + Eigen::MatrixXd(D.asDiagonal());
  EXPECT_LT((Eigen::MatrixXd(A) - expected).norm(), 1e-12 * expected.norm());
  const Eigen::VectorXd exactRotationTermTimesV = forceDerivative(fem, x, v) - K * v;
  EXPECT_GT((exactRotationTermTimesV - rotationTerm * v).norm(),
            1e-2 * exactRotationTermTimesV.norm());  // modes were dropped from the matrix
  const Eigen::VectorXd expectedForce = f - 0.7 * (K * v) - 0.4 * exactRotationTermTimesV;
  // (Differences of the force are good to about 1e-7 of the term here; the
  // matrix's K_rot in its place is off by half of it.)
  EXPECT_LT((fTerms - expectedForce).norm(), 1e-6 * (0.4 * exactRotationTermTimesV).norm());
  EXPECT_GT((expectedForce - f).norm(), 0.1 * f.norm());             // the velocity terms count
  EXPECT_GT(rotationTerm.norm(), 1e-3 * Eigen::MatrixXd(K).norm());  // and so does K_rot
  Eigen::VectorXd wrong(3);
  terms.velocity = &wrong;
  EXPECT_THROW(fem.update(x, fTerms, A, terms), Error);
}

// The force queried between steps is the element pass's own, f_el - beta K
// v, without its matrix; and it leaves the pass's state alone (the next
// update() gives what it gave before the query).
TEST(CorotatedFem, DampedElasticForceIsTheElementPasssForce) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 0.1);
  Eigen::VectorXd x = fem.restPositions(), v(fem.dofCount());
  for (Index i = 0; i < x.size(); ++i) {
    x[i] += noise(rng);
    v[i] = noise(rng);
  }
  Eigen::VectorXd f, fDamped, fAgain;
  SparseMatrix K = fem.pattern(), A = fem.pattern();
  fem.update(x, f, K);
  CorotatedFem::SystemTerms terms;
  terms.velocity = &v;
  terms.velocityWeight = 0.7;
  fem.update(x, fDamped, A, terms);
  ASSERT_GT((fDamped - f).norm(), 0.1 * f.norm());  // the damping counts
  EXPECT_LT((fem.dampedElasticForce(x, v, 0.7) - fDamped).norm(), 1e-9 * fDamped.norm());
  EXPECT_LT((fem.dampedElasticForce(x, v, 0) - f).norm(), 1e-9 * f.norm());
  // Internal forces balance: they sum to zero over the body.
  const Eigen::VectorXd q = fem.dampedElasticForce(x, v, 0.7);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (Index node = 0; node < fem.nodeCount(); ++node) sum += q.segment<3>(3 * node);
  EXPECT_LT(sum.norm(), 1e-9 * q.norm());
  fem.update(x, fAgain, A, terms);
  EXPECT_EQ(fAgain, fDamped);
}

// Rotated and stretched by 5% in every direction (plus a little noise), every
// element is under tension, where no mode of the rotation term is dropped:
// K + K_rot is then the exact derivative of the force, -df/dx, as central
// differences of the force show, and K alone is off by K_rot.
TEST(CorotatedFem, RotationTermCompletesTheTangentUnderTension) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 1);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  Eigen::VectorXd x = linearlyMapped(fem, 1.05 * Q);
  for (Index i = 0; i < x.size(); ++i) x[i] += 1e-3 * noise(rng);
  const Eigen::MatrixXd full = tangent(fem, x, 1, 1), warped = tangent(fem, x, 1, 0);
  for (int direction = 0; direction < 4; ++direction) {
    Eigen::VectorXd d(fem.dofCount());
    for (Index i = 0; i < d.size(); ++i) d[i] = noise(rng);
    const Eigen::VectorXd derivative = forceDerivative(fem, x, d);
    const double fullError = (full * d - derivative).norm() / derivative.norm();
    const double warpedError = (warped * d - derivative).norm() / derivative.norm();
    EXPECT_LT(fullError, 1e-6) << "direction " << direction;
    EXPECT_GT(warpedError, 1e-3) << "direction " << direction;
  }
}

// The rotation term is positive semidefinite however the elements are
// deformed (its negative modes, under compression, are dropped), and so is
// the whole tangent: zero at the rest shape and under uniform compression
// (every mode negative), nonzero under uniform stretch and under large
// random deformations that invert some elements.
TEST(CorotatedFem, RotationTermIsPositiveSemidefinite) {
  const TetMesh mesh = test::tetGrid(3, 2, 2, {3, 2, 2});
  CorotatedFem fem(mesh, material());
  const Eigen::VectorXd X = fem.restPositions();
  const double scale = tangent(fem, X, 1, 0).norm();
  EXPECT_LT(tangent(fem, X, 0, 1).norm(), 1e-12 * scale);
  EXPECT_LT(tangent(fem, 0.9 * X, 0, 1).norm(), 1e-12 * scale);
  EXPECT_GT(tangent(fem, 1.1 * X, 0, 1).norm(), 1e-2 * scale);
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0, 0.4);
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd x = X;
    for (Index i = 0; i < x.size(); ++i) x[i] += noise(rng);
    for (const double s : {0.0, 1.0}) {
      const Eigen::MatrixXd A = tangent(fem, x, s, 1);
      const Eigen::VectorXd values =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
      EXPECT_GT(values.minCoeff(), -1e-12 * values.maxCoeff()) << "trial " << trial << " s " << s;
      EXPECT_GT(values.maxCoeff(), 1e-2 * scale) << "trial " << trial << " s " << s;
    }
  }
}

TEST(CorotatedFem, LumpedMassSumsToTotalMass) {
  const TetMesh mesh = test::tetGrid(2, 3, 4, {2, 3, 4});
  ElasticMaterial m = material();
  m.density = 7;
  const CorotatedFem fem(mesh, m);
  EXPECT_NEAR(fem.lumpedMass().sum(), 3 * 7 * 24.0, 1e-9);
}

// Two blocks side by side in one mesh, the second of another material (a
// region): the element pass, the mass, the energy and the stresses are
// those of two meshes, each of its own material, by both kernels.
TEST(CorotatedFem, AMaterialRegionActsAsAMeshOfItsOwnMaterial) {
  const TetMesh a = test::tetGrid(3, 1, 1, {3, 1, 1});
  TetMesh b = test::tetGrid(2, 2, 1, {2, 2, 1});
  b.nodes.col(0).array() += 5;
  TetMesh both;
  both.nodes.resize(a.nodeCount() + b.nodeCount(), 3);
  both.nodes << a.nodes, b.nodes;
  both.elements.resize(a.elementCount() + b.elementCount(), 4);
  both.elements << a.elements, (b.elements.array() + static_cast<int>(a.nodeCount())).matrix();
  ElasticMaterial other = material();
  other.youngsModulus = 7000;
  other.poissonRatio = 0.45;
  other.density = 300;
  const MaterialRegion region{a.elementCount(), b.elementCount(), other};
  CorotatedFem alone(a, material()), otherAlone(b, other);
  for (const SimdKernel kernel : {SimdKernel::Fastest, SimdKernel::Baseline}) {
    CorotatedFem fem(both, material(), std::span(&region, 1));
    fem.setKernel(kernel);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0, 0.1);
    Eigen::VectorXd x = fem.restPositions(), v(fem.dofCount());
    for (Index i = 0; i < x.size(); ++i) {
      x[i] += noise(rng);
      v[i] = noise(rng);
    }
    const Index na = 3 * a.nodeCount(), nb = 3 * b.nodeCount();
    CorotatedFem::SystemTerms terms;
    terms.stiffnessScale = 0.01;
    terms.velocity = &v;
    terms.velocityWeight = 0.2;
    terms.rotationScale = 0.005;
    terms.rotationVelocityWeight = 0.1;
    Eigen::VectorXd f, fa, fb;
    SparseMatrix A = fem.pattern(), Aa = alone.pattern(), Ab = otherAlone.pattern();
    fem.update(x, f, A, terms);
    CorotatedFem::SystemTerms termsA = terms, termsB = terms;
    const Eigen::VectorXd va = v.head(na), vb = v.tail(nb);
    termsA.velocity = &va;
    termsB.velocity = &vb;
    alone.update(x.head(na), fa, Aa, termsA);
    otherAlone.update(x.tail(nb), fb, Ab, termsB);
    EXPECT_LT((f.head(na) - fa).norm(), 1e-12 * fa.norm());
    EXPECT_LT((f.tail(nb) - fb).norm(), 1e-12 * fb.norm());
    const Eigen::MatrixXd dense(A);
    EXPECT_LT((dense.topLeftCorner(na, na) - Eigen::MatrixXd(Aa)).norm(),
              1e-12 * Eigen::MatrixXd(Aa).norm());
    EXPECT_LT((dense.bottomRightCorner(nb, nb) - Eigen::MatrixXd(Ab)).norm(),
              1e-12 * Eigen::MatrixXd(Ab).norm());
    EXPECT_NEAR(fem.lumpedMass().sum(), 3 * (material().density * 3.0 + 300 * 4.0), 1e-9);
    EXPECT_NEAR(fem.elasticEnergy(x),
                alone.elasticEnergy(x.head(na)) + otherAlone.elasticEnergy(x.tail(nb)),
                1e-12 * fem.elasticEnergy(x));
    const Eigen::VectorXd stress = fem.elementMeasures(x).vonMisesStress;
    const Eigen::VectorXd stressB = otherAlone.elementMeasures(x.tail(nb)).vonMisesStress;
    EXPECT_LT((stress.tail(b.elementCount()) - stressB).norm(), 1e-12 * stressB.norm());
    EXPECT_TRUE(
        fem.elementStiffness(a.elementCount()).isApprox(otherAlone.elementStiffness(0), 1e-12));
  }
  const MaterialRegion beyond{a.elementCount(), b.elementCount() + 1, other};
  try {
    CorotatedFem fem(both, material(), std::span(&beyond, 1));
    ADD_FAILURE() << "a region beyond the elements was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("material region 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tetskin
