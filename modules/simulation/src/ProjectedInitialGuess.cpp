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
  // A basis of the span: Q = S V D^-1/2 over the eigenpairs (V, D) of S^T S
  // that are not negligible (then Q^T Q = I up to the Gram matrix's
  // rounding); the columns of the others are zero.
  const Eigen::SelfAdjointEigenSolver<Square> eigen(gram);
  if (eigen.info() != Eigen::Success) return;
  const double largest = eigen.eigenvalues()[K - 1];
  if (!(largest > 0)) return;  // only zeros stored
  int rank = 0;
  Square toBasis = Square::Zero();  // Q = S toBasis
  for (; rank < K; ++rank) {
    const double value = eigen.eigenvalues()[K - 1 - rank];
    if (!(value >
          ProjectedInitialGuess::kDependence * ProjectedInitialGuess::kDependence * largest))
      break;
    toBasis.col(rank) = eigen.eigenvectors().col(K - 1 - rank) / std::sqrt(value);
  }

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
  const Eigen::MatrixXd system =
      0.5 * (reduced.topLeftCorner(rank, rank) + reduced.topLeftCorner(rank, rank).transpose());
  const Eigen::LLT<Eigen::MatrixXd> factor(system);
  if (factor.info() != Eigen::Success) return;  // A not SPD on the span
  Column coefficients = Column::Zero();
  coefficients.head(rank) = factor.solve(basisB.head(rank));
  if (!coefficients.allFinite()) return;
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
