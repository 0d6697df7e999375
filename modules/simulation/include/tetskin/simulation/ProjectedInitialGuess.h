// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Initial guesses for a sequence of related SPD systems A_n x_n = b_n, one per
// time step: the vector of the span of the last few solutions closest to the
// new solution in the energy norm of the new A (P. F. Fischer, "Projection
// techniques for iterative solution of Ax = b with successive right-hand
// sides", Comput. Methods Appl. Mech. Engrg. 163, 1998; here the basis is
// re-projected with each step's A, since the corotated stiffness changes).
//
// The span holds the last solution itself, and its differences: the plain
// warm start, the linear and higher extrapolations in time, and any other
// combination. The projection is at least as close to the solution, in the
// A-norm that CG's error is measured in, as each of them; a smooth motion is
// predicted to a small part of its step (a falling body almost exactly), so
// CG starts nearer and needs fewer iterations.
//
// It costs one pass over A for all stored vectors together and three passes
// over them (O(n k^2), in parallel): the basis of the span is found in k
// dimensions, from the eigenvectors of the stored solutions' Gram matrix,
// instead of by Gram-Schmidt over n. Directions in which the solutions vary
// by less than kDependence of the largest one are left out: there the Gram
// matrix's rounding (1e-16 of its largest eigenvalue) would no longer give
// a basis vector that is nearly orthogonal to the others, and such
// directions are far below a solve's tolerance.

#include "tetskin/simulation/NodeBlockMatrix.h"

namespace tetskin {

class ProjectedInitialGuess {
 public:
  // Keeps up to `capacity` (0..kMaxProductColumns) solutions; 0 stores none
  // and guess() leaves its x as it is.
  explicit ProjectedInitialGuess(int capacity);

  int capacity() const { return capacity_; }
  int size() const { return size_; }

  // Relative size (singular value of the stored solutions over the largest)
  // below which a direction of their span is left out.
  static constexpr double kDependence = 1e-7;

  // x = the A-orthogonal projection of A^-1 b onto the span of the stored
  // solutions, computed without A^-1: with Q a basis of the span,
  // x = Q (Q^T A Q)^-1 Q^T b. x is left as it is while nothing nonzero is
  // stored. A must be SPD and of the stored vectors' size. The result is the
  // same bits on any number of threads.
  void guess(const NodeBlockMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  // Stores a solution (copied), replacing the oldest once full; a solution of
  // another size than the stored ones starts the store afresh.
  void remember(const Eigen::VectorXd& solution);
  void clear() { size_ = next_ = 0; }

 private:
  int capacity_;
  int size_ = 0, next_ = 0;  // stored count; column written next
  DenseRows solutions_;      // dofs x capacity, a solution per column
  // Scratch: the basis of the span and A times it.
  DenseRows basis_, products_;
};

}  // namespace tetskin
