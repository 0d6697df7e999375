// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include "SampleData.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/ProjectedInitialGuess.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

// An implicit-step-like SPD system M + h^2 K on the sample's level 1.
SparseMatrix stepSystem() {
  const Dataset& d = sampleDataset();
  CorotatedFem fem(extractLevel(d.mesh, 1), ElasticMaterial{});
  Eigen::VectorXd f;
  SparseMatrix A = fem.pattern();
  fem.update(fem.restPositions() + 0.01 * Eigen::VectorXd::Random(fem.dofCount()), f, A);
  A *= 1.0 / 3600.0;
  for (Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += fem.lumpedMass()[i];
  return A;
}

double energyNorm(const SparseMatrix& A, const Eigen::VectorXd& e) {
  return std::sqrt(e.dot(A * e));
}

// Y = A X in one pass equals the column-by-column products, for every
// column count the product takes and with both kernels; more columns are an
// error.
TEST(ProjectedInitialGuess, ManyColumnProductEqualsSingleProducts) {
  const SparseMatrix A = stepSystem();
  const NodeBlockMatrix blocks(A);
  for (SimdKernel kernel : {SimdKernel::Fastest, SimdKernel::Baseline})
    for (int k = 1; k <= kMaxProductColumns; ++k) {
      const DenseRows X = DenseRows::Random(A.rows(), k);
      DenseRows Y;
      multiply(blocks, X, Y, kernel);
      ASSERT_EQ(Y.cols(), k);
      for (int j = 0; j < k; ++j) {
        const Eigen::VectorXd expected = A * Eigen::VectorXd(X.col(j));
        EXPECT_LT((Eigen::VectorXd(Y.col(j)) - expected).norm(), 1e-12 * expected.norm()) << k;
      }
    }
  DenseRows Y;
  EXPECT_THROW(multiply(blocks, DenseRows::Random(A.rows(), kMaxProductColumns + 1), Y), Error);
  EXPECT_THROW(multiply(blocks, DenseRows::Random(A.rows() - 3, 2), Y), Error);
}

// The guess is the energy-norm projection: it equals the solution of the
// small Galerkin system U^T A U c = U^T b built densely, and it is at least
// as close to A^-1 b (in the A-norm) as every stored vector and as zero.
TEST(ProjectedInitialGuess, IsTheEnergyNormProjectionOntoTheStoredSolutions) {
  const SparseMatrix A = stepSystem();
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> direct{Eigen::SparseMatrix<double>(A)};
  const Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXd solution = direct.solve(b);
  ProjectedInitialGuess guess(4);
  Eigen::MatrixXd stored(A.rows(), 4);
  for (int j = 0; j < 4; ++j) {  // "earlier solutions": the solution, perturbed
    stored.col(j) = solution + 0.3 * (j + 1) * Eigen::VectorXd::Random(A.rows());
    guess.remember(stored.col(j));
  }
  EXPECT_EQ(guess.size(), 4);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
  guess.guess(NodeBlockMatrix(A), b, x);
  const Eigen::MatrixXd AU = A * stored;
  const Eigen::VectorXd c = (stored.transpose() * AU).llt().solve(stored.transpose() * b);
  const Eigen::VectorXd reference = stored * c;
  EXPECT_LT((x - reference).norm(), 1e-9 * reference.norm());
  const double error = energyNorm(A, x - solution);
  EXPECT_LT(error, energyNorm(A, solution));  // better than starting from zero
  for (int j = 0; j < 4; ++j) EXPECT_LT(error, energyNorm(A, stored.col(j) - solution));
}

// A solution in the span is found exactly, also when the stored vectors are
// linearly dependent (a repeated solution, a zero vector).
TEST(ProjectedInitialGuess, FindsASolutionInTheSpanDespiteDependentVectors) {
  const SparseMatrix A = stepSystem();
  const Eigen::VectorXd u = Eigen::VectorXd::Random(A.rows());
  const Eigen::VectorXd w = Eigen::VectorXd::Random(A.rows());
  ProjectedInitialGuess guess(5);
  guess.remember(u);
  guess.remember(Eigen::VectorXd::Zero(A.rows()));
  guess.remember(w);
  guess.remember(2 * u - w);  // dependent
  guess.remember(u);          // repeated
  const Eigen::VectorXd solution = 0.7 * u - 1.3 * w;
  const Eigen::VectorXd b = A * solution;
  Eigen::VectorXd x;
  guess.guess(NodeBlockMatrix(A), b, x);
  EXPECT_LT((x - solution).norm(), 1e-10 * solution.norm());
}

// Solutions that differ from each other only slightly, like those of
// successive time steps (here by powers of 1e-2, down to 1e-10 of the first):
// the directions above kDependence are used (the projection of a solution
// made of them is found to 1e-8 of its A-norm), those below (1e-8 and
// 1e-10) are left out, and one thread or two give the same bits.
TEST(ProjectedInitialGuess, UsesCloseSolutionsAndRepeatsOnAnyThreadCount) {
  const SparseMatrix A = stepSystem();
  const NodeBlockMatrix blocks(A);
  const Index n = A.rows();
  std::vector<Eigen::VectorXd> directions;
  for (int j = 0; j < 6; ++j) directions.push_back(Eigen::VectorXd::Random(n));
  ProjectedInitialGuess guess(6);
  Eigen::VectorXd stored = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < 6; ++j) {
    stored += std::pow(1e-2, j) * directions[static_cast<std::size_t>(j)];
    guess.remember(stored);
  }
  // In the span: the first four directions (sizes 1 .. 1e-6).
  const Eigen::VectorXd solution = directions[0] + 1e-4 * directions[2] + 1e-6 * directions[3];
  const Eigen::VectorXd b = A * solution;
  Eigen::VectorXd onOne, onTwo;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    guess.guess(blocks, b, onOne);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    guess.guess(blocks, b, onTwo);
  }
  EXPECT_TRUE(onOne == onTwo);
  EXPECT_LT(energyNorm(A, onTwo - solution), 1e-8 * energyNorm(A, solution));
  // The last direction (1e-10 of the first) is below kDependence: a solution
  // along it alone is not found.
  Eigen::VectorXd x;
  guess.guess(blocks, A * directions[5], x);
  EXPECT_GT(energyNorm(A, x - directions[5]), 0.5 * energyNorm(A, directions[5]));
}

// Only the newest `capacity` solutions are kept; nothing stored (or only
// zeros, or capacity 0) leaves x as it is; sizes are checked.
TEST(ProjectedInitialGuess, KeepsTheNewestAndLeavesXAloneWithoutInformation) {
  const SparseMatrix A = stepSystem();
  const Index n = A.rows();
  auto unit = [n](Index i) { return Eigen::VectorXd(Eigen::VectorXd::Unit(n, i)); };
  ProjectedInitialGuess guess(2);
  for (Index i = 0; i < 3; ++i) guess.remember(unit(i));  // unit(0) is dropped
  EXPECT_EQ(guess.size(), 2);
  // b = A e_0: e_0 is not in span{e_1, e_2}, e_2 is.
  const NodeBlockMatrix blocks(A);
  Eigen::VectorXd x;
  guess.guess(blocks, A * unit(2), x);
  EXPECT_LT((x - unit(2)).norm(), 1e-12);
  guess.guess(blocks, A * unit(0), x);
  EXPECT_GT((x - unit(0)).norm(), 0.5);

  const Eigen::VectorXd start = Eigen::VectorXd::Constant(n, 3.0);
  for (int capacity : {0, 3}) {
    ProjectedInitialGuess empty(capacity);
    if (capacity > 0) empty.remember(Eigen::VectorXd::Zero(n));
    x = start;
    empty.guess(blocks, Eigen::VectorXd::Ones(n), x);
    EXPECT_EQ(x, start) << capacity;
  }
  EXPECT_THROW(ProjectedInitialGuess(-1), Error);
  EXPECT_THROW(ProjectedInitialGuess(kMaxProductColumns + 1), Error);
  ProjectedInitialGuess sized(3);
  sized.remember(Eigen::VectorXd::Ones(6));
  EXPECT_THROW(sized.guess(blocks, Eigen::VectorXd::Ones(n), x), Error);
  sized.remember(Eigen::VectorXd::Ones(n));  // another size: the store starts afresh
  EXPECT_EQ(sized.size(), 1);
}

}  // namespace
}  // namespace tetskin
