// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Prolongation.h"

#include "tetskin/spatial/TetLocator.h"

namespace tetskin {

SparseMatrix nodalProlongation(const TetMesh& coarse, const Points3& fineNodes) {
  const TetLocator locator(coarse);
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(fineNodes.rows()) * 4);
  for (Index v = 0; v < fineNodes.rows(); ++v) {
    const TetLocation at = locator.locate(fineNodes.row(v).transpose());
    for (int k = 0; k < 4; ++k)
      triplets.emplace_back(static_cast<int>(v), coarse.elements(at.element, k), at.barycentric[k]);
  }
  SparseMatrix P(fineNodes.rows(), coarse.nodeCount());
  P.setFromTriplets(triplets.begin(), triplets.end());
  return P;
}

SparseMatrix expandToDofs(const SparseMatrix& nodal) {
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(nodal.nonZeros()) * 3);
  for (int r = 0; r < nodal.outerSize(); ++r)
    for (SparseMatrix::InnerIterator it(nodal, r); it; ++it)
      for (int a = 0; a < 3; ++a) triplets.emplace_back(3 * r + a, 3 * it.col() + a, it.value());
  SparseMatrix P(3 * nodal.rows(), 3 * nodal.cols());
  P.setFromTriplets(triplets.begin(), triplets.end());
  return P;
}

}  // namespace tetskin
