// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Prolongation.h"

#include <Eigen/LU>
#include <limits>

#include "tetskin/spatial/AabbTree.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

Eigen::Vector4d barycentric(const TetMesh& m, Index e, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = m.nodes.row(m.elements(e, 0));
  Eigen::Matrix3d t;
  for (int k = 0; k < 3; ++k) t.col(k) = m.nodes.row(m.elements(e, k + 1)).transpose() - a;
  const Eigen::Vector3d l = t.partialPivLu().solve(p - a);
  return {1 - l.sum(), l[0], l[1], l[2]};
}

// 0 inside; otherwise the squared distance to the nearest face.
double squaredDistance(const TetMesh& m, Index e, const Eigen::Vector3d& p) {
  if (barycentric(m, e, p).minCoeff() >= 0) return 0;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : kFaces)
    best = std::min(best, closestPointOnTriangle(p, m.nodes.row(m.elements(e, f[0])).transpose(),
                                                 m.nodes.row(m.elements(e, f[1])).transpose(),
                                                 m.nodes.row(m.elements(e, f[2])).transpose())
                              .squaredDistance);
  return best;
}

}  // namespace

SparseMatrix nodalProlongation(const TetMesh& coarse, const Points3& fineNodes) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(coarse.elementCount()));
  for (Index e = 0; e < coarse.elementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      boxes[static_cast<std::size_t>(e)].extend(
          coarse.nodes.row(coarse.elements(e, k)).transpose());
  const AabbTree tree(boxes);
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(fineNodes.rows()) * 4);
  for (Index v = 0; v < fineNodes.rows(); ++v) {
    const Eigen::Vector3d p = fineNodes.row(v).transpose();
    int chosen = -1;
    double best = std::numeric_limits<double>::infinity();
    tree.forEachNear(p, best, [&](int e, double& radius2) {
      const double d2 = squaredDistance(coarse, e, p);
      if (d2 < radius2 || (d2 == radius2 && e < chosen)) {
        radius2 = d2;
        chosen = e;
      }
    });
    const Eigen::Vector4d w = barycentric(coarse, chosen, p);
    for (int k = 0; k < 4; ++k)
      triplets.emplace_back(static_cast<int>(v), coarse.elements(chosen, k), w[k]);
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
