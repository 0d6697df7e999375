// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/TetLocator.h"

#include <Eigen/LU>
#include <limits>

#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {

Eigen::Vector4d tetBarycentric(const TetMesh& m, Index e, const Eigen::Vector3d& p) {
  const Eigen::Vector3d a = m.nodes.row(m.elements(e, 0)).transpose();
  Eigen::Matrix3d t;
  for (int k = 0; k < 3; ++k) t.col(k) = m.nodes.row(m.elements(e, k + 1)).transpose() - a;
  const Eigen::Vector3d l = t.partialPivLu().solve(p - a);
  return {1 - l.sum(), l[0], l[1], l[2]};
}

TetLocator::TetLocator(const TetMesh& mesh) : mesh_(mesh) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(mesh.elementCount()));
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      boxes[static_cast<std::size_t>(e)].extend(mesh.nodes.row(mesh.elements(e, k)).transpose());
  tree_ = AabbTree(boxes);
}

double TetLocator::squaredDistance(Index e, const Eigen::Vector3d& p) const {
  if (tetBarycentric(mesh_, e, p).minCoeff() >= 0) return 0;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : kFaces)
    best = std::min(best,
                    closestPointOnTriangle(p, mesh_.nodes.row(mesh_.elements(e, f[0])).transpose(),
                                           mesh_.nodes.row(mesh_.elements(e, f[1])).transpose(),
                                           mesh_.nodes.row(mesh_.elements(e, f[2])).transpose())
                        .squaredDistance);
  return best;
}

TetLocation TetLocator::locate(const Eigen::Vector3d& p) const {
  TetLocation out;
  out.squaredDistance = std::numeric_limits<double>::infinity();
  tree_.forEachNear(p, out.squaredDistance, [&](int e, double& radius2) {
    const double d2 = squaredDistance(e, p);
    if (d2 < radius2 || (d2 == radius2 && e < out.element)) {
      radius2 = d2;
      out.element = e;
    }
  });
  if (out.element >= 0) out.barycentric = tetBarycentric(mesh_, out.element, p);
  return out;
}

}  // namespace tetskin
