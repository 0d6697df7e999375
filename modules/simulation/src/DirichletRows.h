// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Dirichlet conditions on a system with a fixed sparsity pattern: fixed
// dofs get identity rows and columns (the matrix stays symmetric positive
// definite), their prescribed values move to the right-hand side. Which
// entries that touches is found once per set of fixed dofs, so a step costs
// only as much as the fixed part of the matrix.

#include <vector>

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

class DirichletRows {
 public:
  DirichletRows() = default;
  // `fixedDofs`: 1 per fixed row/column of `pattern`.
  DirichletRows(const SparseMatrix& pattern, const std::vector<char>& fixedDofs);

  // Identity rows and columns for the fixed dofs of A (the constructor's
  // pattern). With `rhs`: b_i -= A_ij u_j for free i and fixed j, then b_j =
  // u_j, u = `prescribed` (zero if null).
  void apply(SparseMatrix& A, Eigen::VectorXd* rhs = nullptr,
             const Eigen::VectorXd* prescribed = nullptr) const;

 private:
  struct Entry {
    int row, slot;  // a free row's entry in a fixed column
  };
  std::vector<int> fixedRows_;
  std::vector<Entry> fixedColumnEntries_;
};

}  // namespace tetskin
