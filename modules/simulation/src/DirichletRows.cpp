// SPDX-License-Identifier: AGPL-3.0-or-later
#include "DirichletRows.h"

namespace tetskin {

DirichletRows::DirichletRows(const SparseMatrix& pattern, const std::vector<char>& fixedDofs) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (int row = 0; row < static_cast<int>(pattern.rows()); ++row) {
    if (fixedDofs[static_cast<std::size_t>(row)]) {
      fixedRows_.push_back(row);
      continue;
    }
    for (int s = outer[row]; s < outer[row + 1]; ++s)
      if (fixedDofs[static_cast<std::size_t>(inner[s])]) fixedColumnEntries_.push_back({row, s});
  }
}

void DirichletRows::apply(SparseMatrix& A, Eigen::VectorXd* rhs,
                          const Eigen::VectorXd* prescribed) const {
  double* a = A.valuePtr();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  for (const Entry& entry : fixedColumnEntries_) {
    if (rhs && prescribed) (*rhs)[entry.row] -= a[entry.slot] * (*prescribed)[inner[entry.slot]];
    a[entry.slot] = 0.0;
  }
  for (int row : fixedRows_) {
    for (int s = outer[row]; s < outer[row + 1]; ++s) a[s] = inner[s] == row ? 1.0 : 0.0;
    if (rhs) (*rhs)[row] = prescribed ? (*prescribed)[row] : 0.0;
  }
}

}  // namespace tetskin
