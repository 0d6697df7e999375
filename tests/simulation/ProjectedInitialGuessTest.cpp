// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/ProjectedInitialGuess.h"

namespace tetskin {
namespace {

const std::string kData = std::string(TETSKIN_SOURCE_DIR) + "/data/";

// An implicit-step-like SPD system M + h^2 K on the sample's level 1.
SparseMatrix stepSystem() {
  const Dataset d = loadDataset(kData + "bunny.json");
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
// column count the product takes; more columns are an error.
TEST(ProjectedInitialGuess, ManyColumnProductEqualsSingleProducts) {
  const SparseMatrix A = stepSystem();
  for (int k : {1, 2, 5, kMaxProductColumns}) {
    const DenseRows X = DenseRows::Random(A.rows(), k);
    DenseRows Y;
    multiply(A, X, Y);
    ASSERT_EQ(Y.cols(), k);
    for (int j = 0; j < k; ++j) {
      const Eigen::VectorXd expected = A * Eigen::VectorXd(X.col(j));
      EXPECT_LT((Eigen::VectorXd(Y.col(j)) - expected).norm(), 1e-12 * expected.norm()) << k;
    }
  }
  DenseRows Y;
  EXPECT_THROW(multiply(A, DenseRows::Random(A.rows(), kMaxProductColumns + 1), Y), Error);
  EXPECT_THROW(multiply(A, DenseRows::Random(A.rows() - 3, 2), Y), Error);
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
  guess.guess(A, b, x);
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
  guess.guess(A, b, x);
  EXPECT_LT((x - solution).norm(), 1e-10 * solution.norm());
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
  Eigen::VectorXd x;
  guess.guess(A, A * unit(2), x);
  EXPECT_LT((x - unit(2)).norm(), 1e-12);
  guess.guess(A, A * unit(0), x);
  EXPECT_GT((x - unit(0)).norm(), 0.5);

  const Eigen::VectorXd start = Eigen::VectorXd::Constant(n, 3.0);
  for (int capacity : {0, 3}) {
    ProjectedInitialGuess empty(capacity);
    if (capacity > 0) empty.remember(Eigen::VectorXd::Zero(n));
    x = start;
    empty.guess(A, Eigen::VectorXd::Ones(n), x);
    EXPECT_EQ(x, start) << capacity;
  }
  EXPECT_THROW(ProjectedInitialGuess(-1), Error);
  EXPECT_THROW(ProjectedInitialGuess(kMaxProductColumns + 1), Error);
  ProjectedInitialGuess sized(3);
  sized.remember(Eigen::VectorXd::Ones(6));
  EXPECT_THROW(sized.guess(A, Eigen::VectorXd::Ones(n), x), Error);
  sized.remember(Eigen::VectorXd::Ones(n));  // another size: the store starts afresh
  EXPECT_EQ(sized.size(), 1);
}

}  // namespace
}  // namespace tetskin
