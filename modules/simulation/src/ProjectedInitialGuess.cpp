// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/ProjectedInitialGuess.h"

#include <Eigen/Cholesky>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

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

void ProjectedInitialGuess::guess(const SparseMatrix& A, const Eigen::VectorXd& b,
                                  Eigen::VectorXd& x) {
  if (size_ == 0) return;
  if (A.rows() != solutions_.rows() || b.size() != A.rows())
    throw Error("initial guess: the system does not match the stored solutions");
  // Orthonormal basis, newest solution first, by classical Gram-Schmidt run
  // twice (as orthogonal as Householder's, and matrix-vector products); a
  // solution (numerically) in the span of the newer ones adds nothing.
  basis_.resize(A.rows(), size_);
  int rank = 0;
  for (int age = 0; age < size_; ++age) {
    const int column = (next_ - 1 - age + 2 * capacity_) % capacity_;
    auto q = basis_.col(rank);
    q = solutions_.col(column);
    const double norm = q.norm();
    for (int pass = 0; pass < 2 && rank > 0; ++pass) {
      const Eigen::VectorXd h = basis_.leftCols(rank).transpose() * q;
      q.noalias() -= basis_.leftCols(rank) * h;
    }
    const double remainder = q.norm();
    if (!(remainder > 1e-12 * norm)) continue;  // zero, dependent or not finite
    q /= remainder;
    ++rank;
  }
  if (rank == 0) return;
  rows_ = basis_.leftCols(rank);
  multiply(A, rows_, products_);
  Eigen::MatrixXd gram = rows_.transpose() * products_;  // Q^T A Q
  gram = 0.5 * (gram + gram.transpose()).eval();
  const Eigen::LLT<Eigen::MatrixXd> factor(gram);
  if (factor.info() != Eigen::Success) return;  // A not SPD on the span: keep x
  const Eigen::VectorXd coefficients = factor.solve(rows_.transpose() * b);
  if (!coefficients.allFinite()) return;
  x.noalias() = basis_.leftCols(rank) * coefficients;
}

}  // namespace tetskin
