// SPDX-License-Identifier: AGPL-3.0-or-later
// Preconditioned conjugate gradients in two parallel passes per iteration.
// The textbook loop makes five: the product, the preconditioner, and the
// serial vector updates and dot products between them; on the 12.7k-element
// level those added about two thirds of the product's time to an iteration,
// most of it in the serial updates and in handing work to the other thread
// and back. Here the first pass computes the new search direction p = z + beta p
// together with its product, by the recurrence A p = A z + beta (A p_old) (the
// product is taken of z, which is complete before the pass starts), and the
// second updates x and r, runs a per-node preconditioner on each chunk of
// nodes it has just updated, and forms the dot products for the next alpha
// and beta.

#include <cmath>

#include "NodeChunks.h"
#include "SimdTarget.h"
#include "tetskin/core/Error.h"
#include "tetskin/simulation/LinearSolvers.h"

namespace tetskin {
namespace {

// The first pass on nodes [first, last): p = z + beta p, q = A z + Cz +
// beta q (q holds A p_old; Cz, if given, the coupling springs' C z), and
// the sum of p.q over these nodes.
template <bool kAvx2>
[[gnu::always_inline]] inline double searchDirection(const NodeBlockMatrix& A, Index first,
                                                     Index last, double beta, const double* z,
                                                     const double* Cz, double* p, double* q) {
  double pq = 0;
  for (Index v = first; v != last; ++v) {
    double product[3];
    if constexpr (kAvx2)
      blockRowSumLanes<double __attribute__((vector_size(32)))>(A, v, z, -1, product);
    else
      blockRowSum(A, v, z, -1, product);
    for (Index a = 0; a < 3; ++a) {
      const Index i = 3 * v + a;
      p[i] = z[i] + beta * p[i];
      q[i] = product[a] + (Cz ? Cz[i] : 0.0) + beta * q[i];
      pq += p[i] * q[i];
    }
  }
  return pq;
}

double searchDirectionBaseline(const NodeBlockMatrix& A, Index first, Index last, double beta,
                               const double* z, const double* Cz, double* p, double* q) {
  return searchDirection<false>(A, first, last, beta, z, Cz, p, q);
}

TETSKIN_AVX2_TARGET double searchDirectionAvx2(const NodeBlockMatrix& A, Index first, Index last,
                                               double beta, const double* z, const double* Cz,
                                               double* p, double* q) {
  return searchDirection<true>(A, first, last, beta, z, Cz, p, q);
}

using SearchKernel = double (*)(const NodeBlockMatrix&, Index, Index, double, const double*,
                                const double*, double*, double*);

}  // namespace

SolveStats conjugateGradient(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             const Preconditioner& preconditioner, double tolerance,
                             int maxIterations) {
  // (The full layout check is left to the multigrid's first setup; the copy
  // checks the row lengths.)
  return conjugateGradient(NodeBlockMatrix(A), b, x, preconditioner, tolerance, maxIterations);
}

SolveStats conjugateGradient(const NodeBlockMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                             const Preconditioner& preconditioner, double tolerance,
                             int maxIterations, std::chrono::steady_clock::time_point deadline,
                             const CouplingSprings* coupling) {
  SolveStats stats;
  const bool timed = deadline != std::chrono::steady_clock::time_point::max();
  if (b.size() != A.rows()) throw Error("conjugate gradients: the right-hand side does not fit");
  const double bNorm = b.norm();
  if (x.size() != b.size()) x.setZero(b.size());
  if (bNorm == 0) {
    x.setZero();
    return stats;
  }
  Eigen::VectorXd r(b.size()), z(b.size());
  multiply(A, x, r);
  // C's products: zero but where the springs touch, which product() writes.
  if (coupling && coupling->empty()) coupling = nullptr;
  Eigen::VectorXd Cz;
  if (coupling) {
    Cz.setZero(b.size());
    coupling->product(x.data(), Cz.data());
    r += Cz;
  }
  r = b - r;
  stats.relativeResidual = r.norm() / bNorm;
  if (stats.relativeResidual <= tolerance) return stats;

  NodeChunks<Eigen::Vector3d> chunks(A.nodeCount());
  const bool perNode = preconditioner.actsPerNode();
  const auto chunkDot = [&](Index first, Index last) {
    const Index count = 3 * (last - first);
    return r.segment(3 * first, count).dot(z.segment(3 * first, count));
  };
  // z = M^-1 r and r.z.
  const auto precondition = [&] {
    if (!perNode) preconditioner.apply(r, z);
    return chunks.sum(
        [&](Index first, Index last) {
          if (perNode) preconditioner.applyToNodes(first, last, r.data(), z.data());
          return Eigen::Vector3d(chunkDot(first, last), 0, 0);
        },
        Eigen::Vector3d::Zero())[0];
  };
  double rz = precondition();

  const SearchKernel search =
      chooseKernel<SearchKernel>(SimdKernel::Fastest, searchDirectionAvx2, searchDirectionBaseline);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(b.size()), q = Eigen::VectorXd::Zero(b.size());
  double beta = 0;
  for (stats.iterations = 1; stats.iterations <= maxIterations; ++stats.iterations) {
    if (timed && std::chrono::steady_clock::now() >= deadline) {
      stats.stoppedAtDeadline = true;
      --stats.iterations;  // (this one not begun)
      break;
    }
    if (coupling) coupling->product(z.data(), Cz.data());
    const double pq = chunks.sum(
        [&](Index first, Index last) {
          return Eigen::Vector3d(search(A, first, last, beta, z.data(),
                                        coupling ? Cz.data() : nullptr, p.data(), q.data()),
                                 0, 0);
        },
        Eigen::Vector3d::Zero())[0];
    if (!(pq > 0)) break;  // not positive definite along p (should not happen)
    const double alpha = rz / pq;
    // r.r, r.z_old (for Polak-Ribiere), and r.z where z is updated here.
    const Eigen::Vector3d sums = chunks.sum(
        [&](Index first, Index last) {
          Eigen::Vector3d s = Eigen::Vector3d::Zero();
          for (Index i = 3 * first; i != 3 * last; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
            s[0] += r[i] * r[i];
            s[1] += r[i] * z[i];
          }
          if (perNode) {
            preconditioner.applyToNodes(first, last, r.data(), z.data());
            s[2] = chunkDot(first, last);
          }
          return s;
        },
        Eigen::Vector3d::Zero());
    stats.relativeResidual = std::sqrt(sums[0]) / bNorm;
    if (stats.relativeResidual <= tolerance) break;
    const double rzNew = perNode ? sums[2] : precondition();
    // Polak-Ribiere beta, r.(z - z_old) / r_old.z_old: the same as the usual
    // r.z / r_old.z_old for an exactly symmetric preconditioner, and keeps
    // CG converging when the preconditioner is only nearly so (a V-cycle in
    // single precision).
    beta = (rzNew - sums[1]) / rz;
    rz = rzNew;
  }
  stats.iterations = std::min(stats.iterations, maxIterations);
  return stats;
}

}  // namespace tetskin
