// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>

#include "DirichletRows.h"
#include "SampleData.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/CouplingSprings.h"
#include "tetskin/simulation/GridHierarchy.h"
#include "tetskin/simulation/LinearSolvers.h"
#include "tetskin/simulation/Prolongation.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

// An implicit step's matrix at the rest shape: M + h^2 K.
SparseMatrix restStepMatrix(const TetMesh& mesh, const SimulationOptions& options) {
  CorotatedFem fem(mesh, options.material);
  Eigen::VectorXd f;
  SparseMatrix A = fem.pattern();
  fem.update(fem.restPositions(), f, A);
  A *= options.timeStep * options.timeStep;
  for (Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += fem.lumpedMass()[i];
  return A;
}

TEST(Prolongation, RowsSumToOneAndLinearFieldsAreExact) {
  const Dataset& d = sampleDataset();
  const TetMesh coarse = extractLevel(d.mesh, 0);
  const TetMesh fine = extractLevel(d.mesh, 1);
  const SparseMatrix P = nodalProlongation(coarse, fine.nodes);
  EXPECT_EQ(P.rows(), fine.nodeCount());
  EXPECT_EQ(P.cols(), coarse.nodeCount());
  const Eigen::VectorXd ones = P * Eigen::VectorXd::Ones(P.cols());
  EXPECT_LT((ones.array() - 1).abs().maxCoeff(), 1e-12);
  // u = A X + b on the coarse nodes is interpolated exactly to the fine nodes.
  const Eigen::Vector3d a(0.3, -1.2, 0.7);
  const Eigen::VectorXd coarseField =
      coarse.nodes * a + Eigen::VectorXd::Constant(coarse.nodeCount(), 2.0);
  const Eigen::VectorXd expected =
      fine.nodes * a + Eigen::VectorXd::Constant(fine.nodeCount(), 2.0);
  EXPECT_LT((P * coarseField - expected).cwiseAbs().maxCoeff(), 1e-9);
  const SparseMatrix P3 = expandToDofs(P);
  EXPECT_EQ(P3.rows(), 3 * fine.nodeCount());
  EXPECT_EQ(P3.nonZeros(), 3 * P.nonZeros());
}

// One implicit step's system of the sample dataset's level 1, solved three ways.
TEST(Solvers, CgAndMultigridAgreeWithADirectSolve) {
  const Dataset& d = sampleDataset();
  SimulationOptions options;
  options.solver = SolverKind::Multigrid;
  Simulation sim(d.mesh, 1, options);
  makeScenario("sag")->setUp(sim);
  // Build the system by hand like the stepper does (K at rest, gravity load).
  CorotatedFem local(sim.restMesh(), options.material);
  Eigen::VectorXd f;
  SparseMatrix K = local.pattern();
  local.update(local.restPositions(), f, K);
  const double h = options.timeStep;
  SparseMatrix A = (h * h) * K;
  for (Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += local.lumpedMass()[i];
  Eigen::VectorXd b =
      h * local.lumpedMass().cwiseProduct(Eigen::VectorXd::LinSpaced(A.rows(), -1, 1));

  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(A);
  const Eigen::VectorXd reference = direct.solve(b);

  BlockJacobi jacobi;
  jacobi.setup(A);
  Eigen::VectorXd xCg = Eigen::VectorXd::Zero(b.size());
  const SolveStats cg = conjugateGradient(A, b, xCg, jacobi, 1e-10, 5000);

  std::vector<SparseMatrix> prolongations = {
      nodalProlongation(extractLevel(d.mesh, 0), sim.restMesh().nodes)};
  MultigridPreconditioner mg(prolongations);
  mg.setup(A);
  Eigen::VectorXd xMg = Eigen::VectorXd::Zero(b.size());
  const SolveStats mgStats = conjugateGradient(A, b, xMg, mg, 1e-10, 5000);

  // The same over the solver's own grid levels (GridHierarchy.h).
  MultigridPreconditioner grids(enclosingGrids(sim.restMesh()).prolongations());
  EXPECT_EQ(grids.levelCount(), 2);
  grids.setup(A);
  Eigen::VectorXd xGrids = Eigen::VectorXd::Zero(b.size());
  const SolveStats gridStats = conjugateGradient(A, b, xGrids, grids, 1e-10, 5000);

  EXPECT_LT((xCg - reference).norm() / reference.norm(), 1e-8);
  EXPECT_LT((xMg - reference).norm() / reference.norm(), 1e-8);
  EXPECT_LT((xGrids - reference).norm() / reference.norm(), 1e-8);
  EXPECT_LT(mgStats.iterations, cg.iterations);
  EXPECT_LT(gridStats.iterations * 2, cg.iterations);
  // Every smoother (Chebyshev, the default, above) solves it too.
  for (int degree : {1, 3})
    for (MultigridSmoother smoother :
         {MultigridSmoother::GaussSeidel, MultigridSmoother::Chebyshev}) {
      MultigridPreconditioner other(prolongations);
      other.setSmoother(smoother, degree);
      other.setup(A);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
      const SolveStats stats = conjugateGradient(A, b, x, other, 1e-10, 5000);
      EXPECT_LT((x - reference).norm() / reference.norm(), 1e-8) << degree;
      EXPECT_LT(stats.iterations, cg.iterations) << degree;
    }
  EXPECT_THROW(mg.setSmoother(MultigridSmoother::Chebyshev, 0), Error);

  // Coarse operators reused from an earlier system: still the exact solution
  // of this one, with a few iterations more at most.
  MultigridPreconditioner reused(prolongations);
  reused.setCoarseReuse(3);
  SparseMatrix earlier = A;
  earlier *= 0.7;  // a different (still SPD) system first
  reused.setup(earlier);
  reused.setup(A);  // keeps the coarse operators of `earlier`
  MultigridPreconditioner ofEarlier(prolongations);
  ofEarlier.setup(earlier);
  const Eigen::SparseMatrix<double> kept(reused.coarseOperator(1));
  EXPECT_EQ((kept - Eigen::SparseMatrix<double>(ofEarlier.coarseOperator(1))).norm(), 0.0);
  EXPECT_GT((kept - Eigen::SparseMatrix<double>(mg.coarseOperator(1))).norm(), 0.1 * kept.norm());
  Eigen::VectorXd xReused = Eigen::VectorXd::Zero(b.size());
  const SolveStats reusedStats = conjugateGradient(A, b, xReused, reused, 1e-10, 5000);
  EXPECT_LT((xReused - reference).norm() / reference.norm(), 1e-8);
  EXPECT_LT(reusedStats.iterations, cg.iterations);
  std::printf("multigrid CG with coarse operators of 0.7 A: %d iterations\n",
              reusedStats.iterations);
  std::printf("iterations to 1e-10: block-Jacobi CG %d, multigrid CG %d (grid levels %d)\n",
              cg.iterations, mgStats.iterations, gridStats.iterations);
  // The streamed Galerkin product equals the plain sparse product.
  const SparseMatrix P3 = expandToDofs(prolongations[0]);
  SparseMatrix plain = SparseMatrix(P3.transpose()) * A * P3;
  for (int row = 0; row < plain.rows(); ++row)  // coarse nodes no fine node reaches
    if (plain.coeff(row, row) == 0.0) plain.coeffRef(row, row) = 1.0;
  EXPECT_LT((Eigen::SparseMatrix<double>(mg.coarseOperator(1)) - Eigen::SparseMatrix<double>(plain))
                .norm(),
            1e-12 * plain.norm());
  // Coarse operators stay symmetric positive definite.
  const SparseMatrix& coarse = mg.coarseOperator(1);
  EXPECT_LT((Eigen::SparseMatrix<double>(coarse) - Eigen::SparseMatrix<double>(coarse.transpose()))
                .norm(),
            1e-9 * coarse.norm());
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt((Eigen::SparseMatrix<double>(coarse)));
  EXPECT_EQ(llt.info(), Eigen::Success);
}

// Block-Jacobi applied to the whole vector at once: CG then takes its path
// for preconditioners that do not act per node (the multigrid's), with the
// same arithmetic as the fused per-node path.
class WholeVectorJacobi : public Preconditioner {
 public:
  void setup(const SparseMatrix& A) override { jacobi_.setup(A); }
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override { jacobi_.apply(r, z); }

 private:
  BlockJacobi jacobi_;
};

// CG's dot products are summed over fixed chunks of nodes: one thread or two
// give the same bits. Its residual, kept by recurrence (r -= alpha A p, A p
// itself by recurrence), is the true one; the preconditioner's per-node path
// and its whole-vector path agree.
TEST(Solvers, ConjugateGradientIsReproducibleAndItsResidualIsTrue) {
  const Dataset& d = sampleDataset();
  const TetMesh mesh = extractLevel(d.mesh, 2);  // 3270 nodes: 26 chunks
  ElasticMaterial material;
  material.youngsModulus = 2e7;  // stiff: a few hundred iterations
  CorotatedFem fem(mesh, material);
  Eigen::VectorXd x = fem.restPositions(), f;
  for (Index i = 0; i < x.size(); ++i) x[i] += 1e-3 * std::sin(0.37 * double(i));
  SparseMatrix A = fem.pattern();
  const Eigen::VectorXd mass = fem.lumpedMass();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 1.0 / 3600;
  terms.diagonal = &mass;
  fem.update(x, f, A, terms);
  const Eigen::VectorXd b = f + mass.cwiseProduct(Eigen::VectorXd::LinSpaced(A.rows(), -1, 2));
  const NodeBlockMatrix blocks(A);

  const auto solve = [&](const Preconditioner& preconditioner, int threads, SolveStats& stats) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    Eigen::VectorXd solution = Eigen::VectorXd::Zero(b.size());
    stats = conjugateGradient(blocks, b, solution, preconditioner, 1e-9, 5000);
    return solution;
  };
  BlockJacobi jacobi;
  jacobi.setup(A);
  WholeVectorJacobi wholeVector;
  wholeVector.setup(A);
  SolveStats one, two, whole;
  const Eigen::VectorXd onOne = solve(jacobi, 1, one);
  const Eigen::VectorXd onTwo = solve(jacobi, 2, two);
  const Eigen::VectorXd ofWhole = solve(wholeVector, 2, whole);
  std::printf("CG to 1e-9 at E = 2e7: %d iterations\n", one.iterations);
  EXPECT_GT(one.iterations, 100);
  EXPECT_EQ(one.iterations, two.iterations);
  EXPECT_TRUE(onOne == onTwo) << "max difference " << (onOne - onTwo).cwiseAbs().maxCoeff();
  const double trueResidual = (b - A * onTwo).norm() / b.norm();
  EXPECT_LE(two.relativeResidual, 1e-9);
  EXPECT_LT(trueResidual, 2e-9);
  EXPECT_NEAR(trueResidual, two.relativeResidual, 0.5 * two.relativeResidual);
  EXPECT_NEAR(whole.iterations, two.iterations, 1);
  EXPECT_LT((ofWhole - onTwo).norm(), 1e-9 * onTwo.norm());
  // A preconditioner that does not act per node refuses to be applied so.
  Eigen::VectorXd r = b, z(b.size());
  EXPECT_THROW(wholeVector.applyToNodes(0, 1, r.data(), z.data()), Error);
}

// Coupling springs (CouplingSprings.h) between far nodes of a small mesh,
// in the three places a step puts them: their diagonal blocks in A, the
// rest in CG's products, the held nodes eliminated with their prescribed
// dv on the right-hand side. CG then solves the whole system, checked
// against a dense solve of A + sum s u u^T with the held rows and columns
// eliminated by hand.
// Stiff springs between far nodes (as between two bodies' nodes): the
// preconditioner that sweeps them (SpringGaussSeidel) is symmetric and
// positive (CG's need), CG with it solves the same system as with block
// Jacobi, and in fewer iterations.
TEST(Solvers, SpringGaussSeidelSeesTheCouplingSprings) {
  const TetMesh mesh = extractLevel(sampleDataset().mesh, 0);
  SparseMatrix A = restStepMatrix(mesh, SimulationOptions{});
  const Index n = A.rows(), nodes = n / 3;
  const double scale = A.diagonal().mean();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  CouplingSprings springs;
  for (int k = 0; k < 60; ++k) {  // pairs of triples: a vertex's nodes against a triangle's
    const Eigen::Vector3d direction =
        Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    std::vector<CouplingSprings::Entry> entries;
    for (int j = 0; j < 3; ++j) entries.push_back({(k * 3 + j) % nodes, 1.0 / 3});
    for (int j = 0; j < 3; ++j) entries.push_back({(k * 3 + j + nodes / 2) % nodes, -1.0 / 3});
    const double stiffness = 300 * scale;
    springs.add(stiffness, direction, entries);
    for (const auto& e : entries)
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          A.coeffRef(3 * e.node + a, 3 * e.node + c) +=
              stiffness * e.weight * e.weight * direction[a] * direction[c];
  }
  SpringGaussSeidel sweep;
  sweep.setCoupling(&springs);
  sweep.setup(A);
  EXPECT_FALSE(sweep.actsPerNode());
  Eigen::VectorXd r1 = Eigen::VectorXd::Random(n), r2 = Eigen::VectorXd::Random(n), z1, z2;
  sweep.apply(r1, z1);
  sweep.apply(r2, z2);
  EXPECT_NEAR(r1.dot(z2), r2.dot(z1), 1e-12 * std::abs(r1.dot(z2)));
  EXPECT_GT(r1.dot(z1), 0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
  BlockJacobi jacobi;
  jacobi.setup(A);
  Eigen::VectorXd withJacobi = Eigen::VectorXd::Zero(n), withSweep = withJacobi;
  const auto never = std::chrono::steady_clock::time_point::max();
  const SolveStats j =
      conjugateGradient(NodeBlockMatrix(A), b, withJacobi, jacobi, 1e-10, 5000, never, &springs);
  const SolveStats g =
      conjugateGradient(NodeBlockMatrix(A), b, withSweep, sweep, 1e-10, 5000, never, &springs);
  std::printf("CG iterations: block Jacobi %d, with the springs swept %d\n", j.iterations,
              g.iterations);
  EXPECT_LE(j.relativeResidual, 1e-10);
  EXPECT_LE(g.relativeResidual, 1e-10);
  EXPECT_LT((withSweep - withJacobi).cwiseAbs().maxCoeff(),
            1e-7 * withJacobi.cwiseAbs().maxCoeff());
  EXPECT_LT(g.iterations, j.iterations);
  // Without springs it is block Jacobi, node by node.
  SpringGaussSeidel plain;
  plain.setup(A);
  EXPECT_TRUE(plain.actsPerNode());
}

TEST(Solvers, ConjugateGradientSolvesTheSystemWithItsCouplingSprings) {
  const TetMesh mesh = extractLevel(sampleDataset().mesh, 0);
  const SimulationOptions options;
  SparseMatrix A = restStepMatrix(mesh, options);
  const Index n = A.rows(), nodes = n / 3;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  CouplingSprings springs;
  Eigen::MatrixXd full = Eigen::MatrixXd(A);
  for (int k = 0; k < 12; ++k) {
    const Eigen::Vector3d direction =
        Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    const double stiffness = 50 * (1 + unit(random));
    std::vector<CouplingSprings::Entry> entries;
    for (int j = 0; j < 5; ++j)  // nodes k*5 + j spread over the mesh: distinct
      entries.push_back({(k * 37 + j * 211) % nodes, unit(random)});
    springs.add(stiffness, direction, entries);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    for (const auto& e : entries) u.segment<3>(3 * e.node) += e.weight * direction;
    full += stiffness * u * u.transpose();
    for (const auto& e : entries)  // A's share: the diagonal block
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          A.coeffRef(3 * e.node + a, 3 * e.node + c) +=
              stiffness * e.weight * e.weight * direction[a] * direction[c];
  }
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
  // Node 37 (in the first spring) is held and prescribed a dv.
  std::vector<char> fixedDofs(static_cast<std::size_t>(n), 0);
  Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(n);
  for (int a = 0; a < 3; ++a) {
    fixedDofs[static_cast<std::size_t>(3 * 37 + a)] = 1;
    prescribed[3 * 37 + a] = 0.01 * (a + 1);
  }
  const Eigen::VectorXd bFull = b - full * prescribed;
  Eigen::VectorXd expected = prescribed;
  std::vector<Index> free;
  for (Index i = 0; i < n; ++i)
    if (!fixedDofs[static_cast<std::size_t>(i)]) free.push_back(i);
  Eigen::MatrixXd reduced(free.size(), free.size());
  Eigen::VectorXd reducedB(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    reducedB[static_cast<Index>(i)] = bFull[free[i]];
    for (std::size_t j = 0; j < free.size(); ++j)
      reduced(static_cast<Index>(i), static_cast<Index>(j)) = full(free[i], free[j]);
  }
  const Eigen::VectorXd reducedX = reduced.llt().solve(reducedB);
  for (std::size_t i = 0; i < free.size(); ++i) expected[free[i]] = reducedX[static_cast<Index>(i)];

  DirichletRows(A, fixedDofs).apply(A, &b, &prescribed);
  springs.eliminate(fixedDofs, prescribed, b);
  BlockJacobi jacobi;
  jacobi.setup(A);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const SolveStats stats =
      conjugateGradient(NodeBlockMatrix(A), b, x, jacobi, 1e-12, 5000,
                        std::chrono::steady_clock::time_point::max(), &springs);
  EXPECT_LE(stats.relativeResidual, 1e-12);
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
  // Without the springs' products CG solves another system.
  Eigen::VectorXd without = Eigen::VectorXd::Zero(n);
  conjugateGradient(NodeBlockMatrix(A), b, without, jacobi, 1e-12, 5000);
  EXPECT_GT((without - expected).cwiseAbs().maxCoeff(), 1e-4 * expected.cwiseAbs().maxCoeff());
}

// A system in other units (here 1e-9 times A and b: a body of a tenth of a
// millimetre has blocks of that order) is the same problem: both
// preconditioners take CG along the same path to the same solution. (Block
// inverses once judged singular by an absolute determinant threshold fell
// back to the identity there, and CG stopped short of the tolerance.)
TEST(Solvers, PreconditionersDoNotDependOnTheSystemsUnits) {
  const Dataset& d = sampleDataset();
  const TetMesh mesh = extractLevel(d.mesh, 2);
  CorotatedFem fem(mesh, ElasticMaterial{});
  Eigen::VectorXd f;
  SparseMatrix A = fem.pattern();
  const Eigen::VectorXd mass = fem.lumpedMass();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 1.0 / 3600;
  terms.diagonal = &mass;
  fem.update(fem.restPositions(), f, A, terms);
  const Eigen::VectorXd b = mass.cwiseProduct(Eigen::VectorXd::LinSpaced(A.rows(), -1, 2));
  const std::vector<SparseMatrix> prolongations = {
      nodalProlongation(extractLevel(d.mesh, 1), mesh.nodes)};
  const auto solve = [&](double units, bool multigrid, SolveStats& stats) {
    const SparseMatrix scaled = units * A;
    BlockJacobi jacobi;
    MultigridPreconditioner mg(prolongations);
    Preconditioner& preconditioner =
        multigrid ? static_cast<Preconditioner&>(mg) : static_cast<Preconditioner&>(jacobi);
    preconditioner.setup(scaled);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    stats = conjugateGradient(scaled, units * b, x, preconditioner, 1e-8, 3000);
    return x;
  };
  for (bool multigrid : {false, true}) {
    SolveStats usual, small;
    const Eigen::VectorXd x = solve(1.0, multigrid, usual);
    const Eigen::VectorXd xSmall = solve(1e-9, multigrid, small);
    std::printf("%s CG to 1e-8: %d iterations, %d with A and b times 1e-9\n",
                multigrid ? "multigrid" : "block-Jacobi", usual.iterations, small.iterations);
    EXPECT_LE(small.relativeResidual, 1e-8);
    EXPECT_NEAR(small.iterations, usual.iterations, 1);
    EXPECT_LT((xSmall - x).norm(), 1e-6 * x.norm());
  }
}

// The node-block kernels equal Eigen's product; the layout check accepts the
// FEM pattern and refuses a matrix whose node rows differ.
TEST(Solvers, NodeBlockProductEqualsTheSparseProduct) {
  const Dataset& d = sampleDataset();
  const TetMesh mesh = extractLevel(d.mesh, 1);
  CorotatedFem fem(mesh, ElasticMaterial{});
  Eigen::VectorXd x = fem.restPositions() + 0.01 * Eigen::VectorXd::Random(fem.dofCount());
  Eigen::VectorXd f;
  SparseMatrix K = fem.pattern();
  fem.update(x, f, K);
  ASSERT_TRUE(hasNodeBlocks(K));
  const Eigen::VectorXd v = Eigen::VectorXd::Random(fem.dofCount());
  Eigen::VectorXd y;
  multiply(K, v, y);
  EXPECT_LT((y - K * v).norm(), 1e-12 * (K * v).norm());
  // Nodal transfer: the same as the expanded scalar matrix.
  const SparseMatrix P = nodalProlongation(extractLevel(d.mesh, 0), mesh.nodes);
  const Eigen::VectorXd coarse = Eigen::VectorXd::Random(3 * P.cols());
  Eigen::VectorXd fine;
  multiplyNodal(P, coarse, fine);
  EXPECT_LT((fine - expandToDofs(P) * coarse).norm(), 1e-12 * fine.norm());
  SparseMatrix scalar(6, 6);
  scalar.setIdentity();
  EXPECT_FALSE(hasNodeBlocks(scalar));  // diagonal entries only, no 3x3 blocks
  BlockJacobi jacobi;
  Eigen::VectorXd solution;
  EXPECT_THROW(conjugateGradient(scalar, Eigen::VectorXd::Ones(6), solution, jacobi, 1e-6, 10),
               Error);
}

// The block copy CG multiplies with holds A's entries: its product equals
// Eigen's (the baseline kernel, and the AVX2 one where the CPU has it; the
// float copy to float rounding), a row can leave out its diagonal block, a copy into
// storage of another shape equals a fresh one, and matrices that are not in
// the node-block layout or vectors of the wrong size are refused.
TEST(Solvers, NodeBlockMatrixProductEqualsTheSparseProduct) {
  const Dataset& d = sampleDataset();
  NodeBlockMatrix blocks;
  for (int level : {1, 0}) {  // the second assign shrinks the storage
    CorotatedFem fem(extractLevel(d.mesh, level), ElasticMaterial{});
    Eigen::VectorXd x = fem.restPositions() + 0.01 * Eigen::VectorXd::Random(fem.dofCount());
    Eigen::VectorXd f, D = fem.lumpedMass();
    SparseMatrix A = fem.pattern();
    CorotatedFem::SystemTerms terms;
    terms.stiffnessScale = 1e-4;
    terms.diagonal = &D;
    fem.update(x, f, A, terms);
    blocks.assign(A);
    EXPECT_EQ(blocks.rows(), A.rows());
    EXPECT_EQ(9 * blocks.blockCount(), A.nonZeros());
    const Eigen::VectorXd v = Eigen::VectorXd::Random(A.rows());
    const Eigen::VectorXd expected = A * v;
    Eigen::VectorXd y, baseline;
    multiply(blocks, v, y);
    EXPECT_LT((y - expected).norm(), 1e-13 * expected.norm());
    multiply(blocks, v, baseline, SimdKernel::Baseline);
    EXPECT_LT((baseline - expected).norm(), 1e-13 * expected.norm());
    Eigen::VectorXd fresh;
    multiply(NodeBlockMatrix(A), v, fresh);
    EXPECT_EQ(fresh, y);
    // The float copy the V-cycle sweeps: the same product to float rounding.
    const FloatNodeBlockMatrix single(A);
    Eigen::VectorXf singleY;
    multiply(single, v.cast<float>(), singleY);
    EXPECT_LT((singleY.cast<double>() - expected).norm(), 1e-5 * expected.norm());
    // A row without its diagonal block (Gauss-Seidel's sum) is the row of
    // A - D, D the diagonal blocks.
    for (Index node : {Index(0), blocks.nodeCount() / 2, blocks.nodeCount() - 1}) {
      double sums[3];
      blockRowSum(blocks, node, v.data(), static_cast<int>(3 * node), sums);
      const Eigen::Vector3d withoutDiagonal =
          expected.segment<3>(3 * node) -
          Eigen::Matrix3d(A.block(3 * node, 3 * node, 3, 3).toDense()) * v.segment<3>(3 * node);
      EXPECT_LT((Eigen::Map<Eigen::Vector3d>(sums) - withoutDiagonal).norm(),
                1e-12 * expected.norm());
    }
    // Each node's diagonal block (the V-cycle inverts them from its copy).
    for (Index node = 0; node < blocks.nodeCount(); ++node) {
      const Eigen::Matrix3d diagonal = A.block(3 * node, 3 * node, 3, 3).toDense();
      ASSERT_EQ(blocks.diagonalBlock(node), diagonal) << "node " << node;
      ASSERT_EQ(single.diagonalBlock(node), diagonal.cast<float>()) << "node " << node;
    }
    // A column is loaded with the entry after it (the fourth lane, left out
    // of the sums): a non-finite x reaches only the rows whose blocks hold
    // its column, through their real entries.
    EXPECT_EQ(blocks.values().size(), 9 * static_cast<std::size_t>(blocks.blockCount()) + 1);
    const Index poisoned = blocks.nodeCount() / 3;
    Eigen::VectorXd withNan = v;
    withNan(3 * poisoned + 1) = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd fromNan, fromNanBaseline;
    multiply(blocks, withNan, fromNan);
    multiply(blocks, withNan, fromNanBaseline, SimdKernel::Baseline);
    Eigen::VectorXf fromNanSingle;
    multiply(single, withNan.cast<float>(), fromNanSingle);
    for (Index node = 0; node < blocks.nodeCount(); ++node) {
      const bool coupled = A.coeff(3 * node, 3 * poisoned + 1) != 0 ||
                           A.coeff(3 * node + 1, 3 * poisoned + 1) != 0 ||
                           A.coeff(3 * node + 2, 3 * poisoned + 1) != 0;
      if (coupled) continue;
      EXPECT_EQ(fromNan.segment<3>(3 * node), y.segment<3>(3 * node)) << "node " << node;
      EXPECT_EQ(fromNanBaseline.segment<3>(3 * node), baseline.segment<3>(3 * node)) << node;
      EXPECT_EQ(fromNanSingle.segment<3>(3 * node), singleY.segment<3>(3 * node)) << node;
    }
    EXPECT_TRUE(std::isnan(fromNan(3 * poisoned)));
    EXPECT_THROW(multiply(blocks, Eigen::VectorXd::Ones(A.rows() + 3), y), Error);
  }
  SparseMatrix scalar(6, 6);
  scalar.setIdentity();
  EXPECT_THROW(blocks.assign(scalar), Error);  // one entry per row, no 3x3 blocks
  try {
    blocks.assign(scalar);
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("node 0"), std::string::npos) << error.what();
  }
  Index badNode = 7;
  EXPECT_FALSE(hasNodeRowLengths(scalar, &badNode));
  EXPECT_EQ(badNode, 0);
  SparseMatrix rectangular(6, 9);
  EXPECT_THROW(blocks.assign(rectangular), Error);
  // Two nodes coupled only to each other: no diagonal blocks, read as zero.
  std::vector<Eigen::Triplet<double, int>> offDiagonal;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      offDiagonal.emplace_back(a, 3 + b, 1.0 + a + 3 * b);
      offDiagonal.emplace_back(3 + b, a, 1.0 + a + 3 * b);
    }
  SparseMatrix coupled(6, 6);
  coupled.setFromTriplets(offDiagonal.begin(), offDiagonal.end());
  blocks.assign(coupled);
  EXPECT_EQ(blocks.diagonalBlock(0), Eigen::Matrix3d::Zero());
  EXPECT_EQ(blocks.diagonalBlock(1), Eigen::Matrix3d::Zero());
}

// The copy in sweep order (the V-cycle's) holds the same blocks as the one
// in column order, each node's split into the blocks of earlier-ranked
// nodes, its own diagonal block, and those of later-ranked nodes (each
// group by column): its product, diagonal blocks and row sums are the
// sparse matrix's, and a plain assign() puts it back in column order.
TEST(Solvers, NodeBlockMatrixInSweepOrderSplitsEachRowByRank) {
  const Dataset& d = sampleDataset();
  CorotatedFem fem(extractLevel(d.mesh, 1), ElasticMaterial{});
  Eigen::VectorXd f, D = fem.lumpedMass();
  SparseMatrix A = fem.pattern();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = 1e-4;
  terms.diagonal = &D;
  fem.update(fem.restPositions() + 0.01 * Eigen::VectorXd::Random(fem.dofCount()), f, A, terms);
  const Index nodes = A.rows() / 3;
  std::vector<int> rank(static_cast<std::size_t>(nodes));
  std::iota(rank.begin(), rank.end(), 0);
  std::shuffle(rank.begin(), rank.end(), std::mt19937(7));
  const Eigen::VectorXd v = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXd expected = A * v;
  NodeBlockMatrix blocks;
  blocks.assignInSweepOrder(A, rank);
  FloatNodeBlockMatrix single;
  single.assignInSweepOrder(A, rank);
  Eigen::VectorXd y;
  multiply(blocks, v, y);
  EXPECT_LT((y - expected).norm(), 1e-13 * expected.norm());
  Eigen::VectorXf singleY;
  multiply(single, v.cast<float>(), singleY);
  EXPECT_LT((singleY.cast<double>() - expected).norm(), 1e-5 * expected.norm());
  int withEarlier = 0, withLater = 0;
  for (Index node = 0; node < nodes; ++node) {
    const auto n = static_cast<std::size_t>(node);
    const int start = blocks.blockStarts()[n], end = blocks.blockStarts()[n + 1];
    const int later = blocks.laterBlocks(node);
    ASSERT_GT(later, start) << "node " << node;
    ASSERT_LE(later, end) << "node " << node;
    ASSERT_EQ(single.laterBlocks(node), later);
    EXPECT_EQ(blocks.columns()[static_cast<std::size_t>(later - 1)], 3 * node) << "node " << node;
    for (int k = start; k < end; ++k) {
      const int column = blocks.columns()[static_cast<std::size_t>(k)];
      const int other = rank[static_cast<std::size_t>(column / 3)];
      if (k < later - 1) {
        EXPECT_LT(other, rank[n]) << "node " << node << ", block " << k;
      }
      if (k >= later) {
        EXPECT_GT(other, rank[n]) << "node " << node << ", block " << k;
      }
      if (k + 1 < later - 1 || (k >= later && k + 1 < end)) {  // within a group
        EXPECT_LT(column, blocks.columns()[static_cast<std::size_t>(k + 1)]) << "node " << node;
      }
    }
    withEarlier += later - 1 > start;
    withLater += later < end;
    const Eigen::Matrix3d diagonal = A.block(3 * node, 3 * node, 3, 3).toDense();
    ASSERT_EQ(blocks.diagonalBlock(node), diagonal) << "node " << node;
    ASSERT_EQ(single.diagonalBlock(node), diagonal.cast<float>()) << "node " << node;
    // The two groups' sums add up to the row without its diagonal block.
    double earlierSums[3], laterSums[3];
    blockRangeSum(blocks, start, later, v.data(), static_cast<int>(3 * node), earlierSums);
    blockRangeSum(blocks, later, end, v.data(), -1, laterSums);
    const Eigen::Vector3d withoutDiagonal =
        expected.segment<3>(3 * node) - diagonal * v.segment<3>(3 * node);
    EXPECT_LT((Eigen::Map<Eigen::Vector3d>(earlierSums) + Eigen::Map<Eigen::Vector3d>(laterSums) -
               withoutDiagonal)
                  .norm(),
              1e-12 * expected.norm());
  }
  EXPECT_GT(withEarlier, nodes / 2);  // a shuffled rank splits most rows both ways
  EXPECT_GT(withLater, nodes / 2);
  blocks.assign(A);
  EXPECT_EQ(blocks.laterBlocks(0), -1);
  EXPECT_TRUE(std::is_sorted(blocks.columns().begin() + blocks.blockStarts()[0],
                             blocks.columns().begin() + blocks.blockStarts()[1]));
  EXPECT_THROW(blocks.assignInSweepOrder(A, std::vector<int>(3, 0)), Error);
}

// The V-cycle is a symmetric operator (forward sweeps before, the exact
// backward sweeps after, P^T down and P up): u . M^-1 v = v . M^-1 u. CG
// needs that; a sweep order that is not exactly reversed breaks it, and so
// does a residual after the first sweep that is not b - A x.
TEST(Solvers, MultigridCycleIsSymmetric) {
  const Dataset& d = sampleDataset();
  SimulationOptions options;
  Simulation sim(d.mesh, 2, options);
  const SparseMatrix A = restStepMatrix(sim.restMesh(), options);
  std::vector<SparseMatrix> prolongations;
  Points3 fineNodes = sim.restMesh().nodes;
  for (int level = 1; level >= 0; --level) {
    const TetMesh coarse = extractLevel(d.mesh, level);
    prolongations.push_back(nodalProlongation(coarse, fineNodes));
    fineNodes = coarse.nodes;
  }
  const Eigen::VectorXd u = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXd v = Eigen::VectorXd::Random(A.rows());
  // Gauss-Seidel: one sweep each way (the first from zero, fused with its
  // residual) and two (the second a full sweep, the residual a product);
  // Chebyshev of degrees 1 to 3 (the same polynomial before and after).
  struct Smoothing {
    MultigridSmoother smoother;
    int count;  // sweeps or degree
  };
  for (const Smoothing smoothing :
       {Smoothing{MultigridSmoother::GaussSeidel, 1}, Smoothing{MultigridSmoother::GaussSeidel, 2},
        Smoothing{MultigridSmoother::Chebyshev, 1}, Smoothing{MultigridSmoother::Chebyshev, 2},
        Smoothing{MultigridSmoother::Chebyshev, 3}}) {
    const bool chebyshev = smoothing.smoother == MultigridSmoother::Chebyshev;
    const std::string name =
        (chebyshev ? "Chebyshev " : "Gauss-Seidel ") + std::to_string(smoothing.count);
    std::vector<Eigen::VectorXd> results;
    for (bool single : {false, true}) {
      MultigridPreconditioner mg(prolongations, chebyshev ? 1 : smoothing.count);
      mg.setSmoother(smoothing.smoother, chebyshev ? smoothing.count : 2);
      mg.setSinglePrecision(single);
      mg.setup(A);
      Eigen::VectorXd Mu, Mv;
      mg.apply(u, Mu);
      mg.apply(v, Mv);
      // Symmetric in double up to rounding; in float up to its rounding.
      EXPECT_NEAR(u.dot(Mv), v.dot(Mu), (single ? 1e-5 : 1e-10) * std::abs(u.dot(Mv))) << name;
      EXPECT_GT(u.dot(Mu), 0) << name;  // and positive
      EXPECT_GT(v.dot(Mv), 0) << name;
      results.push_back(Mu);
    }
    // The float cycle is the double one up to rounding.
    EXPECT_LT((results[1] - results[0]).norm(), 1e-5 * results[0].norm()) << name;
  }
}

// The Chebyshev smoother relaxes every node from its neighbours' old values
// alone: one thread or two give the same bits; and one cycle at least
// halves the energy of the error of A x = r.
TEST(Solvers, ChebyshevCycleIsTheSameOnAnyNumberOfThreads) {
  const Dataset& d = sampleDataset();
  SimulationOptions options;
  Simulation sim(d.mesh, 2, options);
  const SparseMatrix A = restStepMatrix(sim.restMesh(), options);
  const std::vector<SparseMatrix> prolongations = enclosingGrids(sim.restMesh()).prolongations();
  const Eigen::VectorXd r = Eigen::VectorXd::Random(A.rows());
  std::vector<Eigen::VectorXd> results;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    MultigridPreconditioner mg(prolongations);
    mg.setup(A);
    Eigen::VectorXd z;
    mg.apply(r, z);
    results.push_back(z);
  }
  EXPECT_EQ(results[0], results[1]);
  // One application reduces the error of A x = r: |x - M r|_A < |x|_A.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct((Eigen::SparseMatrix<double>(A)));
  const Eigen::VectorXd x = direct.solve(r);
  const Eigen::VectorXd error = x - results[0];
  EXPECT_LT(error.dot(A * error), 0.5 * x.dot(A * x));
}

// A caller's preconditioner (SimulationOptions::preconditioner) is CG's:
// one is made per simulation and set up on every step's system, and block
// Jacobi made by the caller steps exactly as the built-in one does.
TEST(Solvers, ACallersPreconditionerPreconditionsTheStepsCg) {
  struct Counting : BlockJacobi {
    explicit Counting(int* setups) : setups_(setups) {}
    void setup(const SparseMatrix& A) override {
      ++*setups_;
      BlockJacobi::setup(A);
    }
    int* setups_;
  };
  const Dataset& d = sampleDataset();
  int made = 0, setups = 0;
  SimulationOptions builtIn;
  builtIn.solver = SolverKind::ConjugateGradient;
  SimulationOptions given = builtIn;
  given.preconditioner = [&] {
    ++made;
    return std::make_unique<Counting>(&setups);
  };
  Simulation a(d.mesh, 1, builtIn), b(d.mesh, 1, given);
  const auto wobbleA = makeScenario("wobble"), wobbleB = makeScenario("wobble");
  wobbleA->setUp(a);
  wobbleB->setUp(b);
  for (int i = 0; i < 4; ++i) {
    wobbleA->beforeStep(a, a.time());
    wobbleB->beforeStep(b, b.time());
    EXPECT_EQ(a.step().iterations, b.step().iterations);
  }
  EXPECT_EQ(made, 1);
  EXPECT_EQ(setups, 4);
  EXPECT_TRUE(a.state().positions == b.state().positions);
}

}  // namespace
}  // namespace tetskin
