// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/ProjectedInitialGuess.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <string>
#include <utility>

#include "NodeChunks.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {
namespace {

// The k x k parts (k <= 16) are solved on dynamic-size matrices: their cost
// is nothing beside the O(n k^2) passes, and Eigen's eigensolver and
// Cholesky instantiated at 16 fixed sizes took this file 9 to 15 minutes to
// compile.

// A basis of the span of the stored solutions S from their Gram matrix
// S^T S: Q = S V D^-1/2 over the eigenpairs (V, D) that are not negligible
// (then Q^T Q = I up to the Gram matrix's rounding), written to the first
// columns of `toBasis`, the others zero. Returns their count, 0 when the
// eigensolver fails or only zeros are stored.
template <typename Square>
int spanBasis(const Square& gram, Square& toBasis) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen{Eigen::MatrixXd(gram)};
  toBasis.setZero();
  if (eigen.info() != Eigen::Success) return 0;
  const Index k = gram.rows();
  const double largest = eigen.eigenvalues()[k - 1];
  if (!(largest > 0)) return 0;
  int rank = 0;
  for (; rank < k; ++rank) {
    const double value = eigen.eigenvalues()[k - 1 - rank];
    if (!(value >
          ProjectedInitialGuess::kDependence * ProjectedInitialGuess::kDependence * largest))
      break;
    toBasis.col(rank) = eigen.eigenvectors().col(k - 1 - rank) / std::sqrt(value);
  }
  return rank;
}

// The coefficients c of x = Q c: (Q^T A Q) c = Q^T b on the basis's first
// `rank` columns (symmetrized against rounding); false when Q^T A Q is not
// SPD there (A not SPD on the span) or c is not finite.
template <typename Square, typename Column>
bool solveReduced(const Square& reduced, const Column& basisB, int rank, Column& coefficients) {
  const Eigen::MatrixXd system =
      0.5 * (reduced.topLeftCorner(rank, rank) + reduced.topLeftCorner(rank, rank).transpose());
  const Eigen::LLT<Eigen::MatrixXd> factor(system);
  if (factor.info() != Eigen::Success) return false;
  Eigen::VectorXd rhs(rank);
  for (int i = 0; i != rank; ++i) rhs[i] = basisB[i];
  coefficients.head(rank) = factor.solve(rhs);
  return coefficients.allFinite();
}

// The projection with K stored solutions, K fixed at compile time so that
// the per-dof work (K x K outer products) unrolls and stays in registers.
// x is left as it is when nothing usable is stored.
template <int K>
void project(const NodeBlockMatrix& A, const DenseRows& solutions, const Eigen::VectorXd& b,
             DenseRows& basis, DenseRows& products, Eigen::VectorXd& x) {
  using Row = Eigen::Matrix<double, 1, K>;
  using Square = Eigen::Matrix<double, K, K>;
  using Column = Eigen::Matrix<double, K, 1>;
  const Index stride = solutions.cols();  // the store's capacity; columns 0 .. K-1 are used
  const auto solution = [&](Index i) {
    return Eigen::Map<const Row>(solutions.data() + i * stride);
  };
  NodeChunks<Square> squareSums(A.nodeCount());

  // The Gram matrix S^T S of the stored solutions.
  const Square gram = squareSums.sum(
      [&](Index first, Index last) {
        Square sums = Square::Zero();
        for (Index i = 3 * first; i != 3 * last; ++i)
          sums.noalias() += solution(i).transpose() * solution(i);
        return sums;
      },
      Square::Zero());
  if (!gram.allFinite()) return;
  Square toBasis;  // Q = S toBasis
  const int rank = spanBasis(gram, toBasis);
  if (rank == 0) return;

  // Q and Q^T b.
  basis.resize(A.rows(), K);
  NodeChunks<Column> columnSums(A.nodeCount());
  const Column basisB = columnSums.sum(
      [&](Index first, Index last) {
        Column sums = Column::Zero();
        for (Index i = 3 * first; i != 3 * last; ++i) {
          const Row q = solution(i) * toBasis;
          Eigen::Map<Row>(basis.data() + i * K) = q;
          sums += q.transpose() * b[i];
        }
        return sums;
      },
      Column::Zero());

  // Q^T A Q, and its solve on the kept columns.
  multiply(A, basis, products);
  const Square reduced = squareSums.sum(
      [&](Index first, Index last) {
        Square sums = Square::Zero();
        for (Index i = 3 * first; i != 3 * last; ++i)
          sums.noalias() += Eigen::Map<const Row>(basis.data() + i * K).transpose() *
                            Eigen::Map<const Row>(products.data() + i * K);
        return sums;
      },
      Square::Zero());
  Column coefficients = Column::Zero();
  if (!solveReduced(reduced, basisB, rank, coefficients)) return;
  x.resize(A.rows());
  parallelFor<Index>(0, A.rows(), 1024, [&](const auto& range) {
    for (Index i = range.begin(); i != range.end(); ++i)
      x[i] = Eigen::Map<const Row>(basis.data() + i * K).dot(coefficients.transpose());
  });
}

template <int... K>
void projectWith(int k, const NodeBlockMatrix& A, const DenseRows& solutions,
                 const Eigen::VectorXd& b, DenseRows& basis, DenseRows& products,
                 Eigen::VectorXd& x, std::integer_sequence<int, K...>) {
  ((k == K + 1 ? project<K + 1>(A, solutions, b, basis, products, x) : void()), ...);
}

}  // namespace

ProjectedInitialGuess::ProjectedInitialGuess(int capacity) : capacity_(capacity) {
  if (capacity < 0 || capacity > kMaxProductColumns)
    throw Error("the initial guess keeps 0 to " + std::to_string(kMaxProductColumns) +
                " solutions, not " + std::to_string(capacity));
}

void ProjectedInitialGuess::remember(const Eigen::VectorXd& solution) {
  if (capacity_ == 0) return;
  if (solutions_.rows() != solution.size()) {
    solutions_.resize(solution.size(), capacity_);
    clear();
  }
  solutions_.col(next_) = solution;
  next_ = (next_ + 1) % capacity_;
  size_ = std::min(size_ + 1, capacity_);
}

void ProjectedInitialGuess::guess(const NodeBlockMatrix& A, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x) {
  if (size_ == 0) return;
  if (A.rows() != solutions_.rows() || b.size() != A.rows())
    throw Error("initial guess: the system does not match the stored solutions");
  // (The stored solutions are columns 0 .. size_-1.)
  projectWith(size_, A, solutions_, b, basis_, products_, x,
              std::make_integer_sequence<int, kMaxProductColumns>());
}

}  // namespace tetskin
