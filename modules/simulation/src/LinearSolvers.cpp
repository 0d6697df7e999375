// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/LinearSolvers.h"

#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/simulation/GalerkinStream.h"
#include "tetskin/simulation/Prolongation.h"

namespace tetskin {

void multiply(const SparseMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  if (y.size() != A.rows()) y.resize(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* values = A.valuePtr();
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(A.rows()), 1024),
                    [&](const auto& r) {
                      for (int row = r.begin(); row != r.end(); ++row) {
                        double sum = 0;
                        for (int k = outer[row]; k < outer[row + 1]; ++k)
                          sum += values[k] * x[inner[k]];
                        y[row] = sum;
                      }
                    });
}

namespace {

Eigen::Matrix3d diagonalBlock(const SparseMatrix& A, Index node) {
  Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 3; ++a)
    for (SparseMatrix::InnerIterator it(A, 3 * node + a); it; ++it)
      if (it.col() >= 3 * node && it.col() < 3 * node + 3)
        block(a, it.col() - 3 * node) = it.value();
  return block;
}

// One Gauss-Seidel sweep over the rows in the given direction.
void gaussSeidel(const SparseMatrix& A, const Eigen::VectorXd& diagonal, const Eigen::VectorXd& b,
                 Eigen::VectorXd& x, bool forward) {
  const int n = static_cast<int>(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* values = A.valuePtr();
  for (int i = 0; i < n; ++i) {
    const int row = forward ? i : n - 1 - i;
    double sum = b[row];
    for (int k = outer[row]; k < outer[row + 1]; ++k)
      if (inner[k] != row) sum -= values[k] * x[inner[k]];
    x[row] = sum / diagonal[row];
  }
}

}  // namespace

void BlockJacobi::setup(const SparseMatrix& A) {
  const Index nodes = A.rows() / 3;
  inverse_.resize(static_cast<std::size_t>(nodes));
  tbb::parallel_for(Index(0), nodes, [&](Index v) {
    const Eigen::Matrix3d block = diagonalBlock(A, v);
    Eigen::Matrix3d inverse;
    bool invertible = false;
    block.computeInverseWithCheck(inverse, invertible);
    inverse_[static_cast<std::size_t>(v)] = invertible ? inverse : Eigen::Matrix3d::Identity();
  });
}

void BlockJacobi::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (z.size() != r.size()) z.resize(r.size());
  tbb::parallel_for(std::size_t(0), inverse_.size(), [&](std::size_t v) {
    z.segment<3>(3 * static_cast<Index>(v)) = inverse_[v] * r.segment<3>(3 * static_cast<Index>(v));
  });
}

struct MultigridPreconditioner::Impl {
  std::vector<GalerkinStream> streams;  // built on the first setup() after a change
  std::vector<Eigen::VectorXd> diagonals;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> coarsest;
  // Scratch per level: right-hand side, solution, residual.
  mutable std::vector<Eigen::VectorXd> b, x, r;
};

MultigridPreconditioner::MultigridPreconditioner(std::vector<SparseMatrix> nodalProlongations,
                                                 int smoothingSweeps)
    : prolongations_(std::move(nodalProlongations)),
      sweeps_(smoothingSweeps),
      impl_(std::make_shared<Impl>()) {
  setFixedNodes({});
}

MultigridPreconditioner::~MultigridPreconditioner() = default;

void MultigridPreconditioner::setFixedNodes(const std::vector<char>& fixedNodes) {
  nodal_ = prolongations_;
  if (!nodal_.empty() && !fixedNodes.empty()) {
    // Fixed fine nodes must not receive coarse corrections.
    SparseMatrix& P = nodal_[0];
    for (int row = 0; row < P.outerSize(); ++row)
      if (fixedNodes[static_cast<std::size_t>(row)])
        for (SparseMatrix::InnerIterator it(P, row); it; ++it) it.valueRef() = 0;
    P.prune(0.0);
  }
  transfers_.clear();
  restrictions_.clear();
  for (const SparseMatrix& P : nodal_) {
    transfers_.push_back(expandToDofs(P));
    restrictions_.push_back(transfers_.back().transpose());
  }
  impl_->streams.clear();
}

void MultigridPreconditioner::setup(const SparseMatrix& A) {
  operators_.resize(nodal_.size() + 1);
  operators_[0] = A;
  if (impl_->streams.empty()) {
    const SparseMatrix* fine = &A;
    for (std::size_t l = 0; l < nodal_.size(); ++l) {
      impl_->streams.emplace_back(*fine, nodal_[l]);
      fine = &impl_->streams.back().pattern();
    }
  }
  for (std::size_t l = 0; l < nodal_.size(); ++l)
    impl_->streams[l].compute(operators_[l], operators_[l + 1]);
  impl_->diagonals.resize(operators_.size());
  for (std::size_t l = 0; l < operators_.size(); ++l)
    impl_->diagonals[l] = operators_[l].diagonal();
  // With Dirichlet rows removed from P, columns of P can become linearly
  // dependent and the coarsest operator singular. Its null vectors v have
  // P v = 0 and never reach the fine grid, so a tiny shift that makes the
  // factorization possible changes nothing that matters.
  impl_->coarsest.setShift(1e-12 * operators_.back().diagonal().cwiseAbs().maxCoeff());
  impl_->coarsest.compute(Eigen::SparseMatrix<double>(operators_.back()));
  if (impl_->coarsest.info() != Eigen::Success)
    throw Error("multigrid: the coarsest operator could not be factorized");
  impl_->b.resize(operators_.size());
  impl_->x.resize(operators_.size());
  impl_->r.resize(operators_.size());
}

void MultigridPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  Impl& s = *impl_;
  const std::size_t last = operators_.size() - 1;
  s.b[0] = r;
  // Down: pre-smooth from zero, restrict the residual.
  for (std::size_t l = 0; l < last; ++l) {
    s.x[l].setZero(s.b[l].size());
    for (int i = 0; i < sweeps_; ++i)
      gaussSeidel(operators_[l], s.diagonals[l], s.b[l], s.x[l], true);
    multiply(operators_[l], s.x[l], s.r[l]);
    s.r[l] = s.b[l] - s.r[l];
    s.b[l + 1] = restrictions_[l] * s.r[l];
  }
  s.x[last] = s.coarsest.solve(s.b[last]);
  // Up: prolongate the correction, post-smooth backwards (symmetric cycle).
  for (std::size_t l = last; l-- > 0;) {
    s.x[l] += transfers_[l] * s.x[l + 1];
    for (int i = 0; i < sweeps_; ++i)
      gaussSeidel(operators_[l], s.diagonals[l], s.b[l], s.x[l], false);
  }
  z = s.x[0];
}

SolveStats conjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             const Preconditioner& preconditioner, double tolerance,
                             int maxIterations) {
  SolveStats stats;
  const double bNorm = b.norm();
  if (x.size() != b.size()) x.setZero(b.size());
  if (bNorm == 0) {
    x.setZero();
    return stats;
  }
  Eigen::VectorXd r(b.size()), z(b.size()), p(b.size()), Ap(b.size());
  multiply(A, x, Ap);
  r = b - Ap;
  stats.relativeResidual = r.norm() / bNorm;
  if (stats.relativeResidual <= tolerance) return stats;
  preconditioner.apply(r, z);
  p = z;
  double rz = r.dot(z);
  for (stats.iterations = 1; stats.iterations <= maxIterations; ++stats.iterations) {
    multiply(A, p, Ap);
    const double pAp = p.dot(Ap);
    if (!(pAp > 0)) break;  // not positive definite along p (should not happen)
    const double alpha = rz / pAp;
    x += alpha * p;
    r -= alpha * Ap;
    stats.relativeResidual = r.norm() / bNorm;
    if (stats.relativeResidual <= tolerance) break;
    preconditioner.apply(r, z);
    const double rzNew = r.dot(z);
    p = z + (rzNew / rz) * p;
    rz = rzNew;
  }
  stats.iterations = std::min(stats.iterations, maxIterations);
  return stats;
}

}  // namespace tetskin
