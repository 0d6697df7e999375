// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/SurfaceDistance.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/spatial/AabbTree.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {

std::vector<double> distancesToSurface(const Points3& points, const SurfaceMesh& surface) {
  if (surface.triangleCount() == 0) throw Error("distance to a surface without triangles");
  auto corner = [&](Index t, int k) -> Eigen::Vector3d {
    return surface.positions.row(surface.triangles(t, k)).transpose();
  };
  std::vector<Aabb> boxes(static_cast<std::size_t>(surface.triangleCount()));
  for (Index t = 0; t < surface.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) boxes[static_cast<std::size_t>(t)].extend(corner(t, k));
  const AabbTree tree(boxes);
  std::vector<double> distances(static_cast<std::size_t>(points.rows()));
  parallelFor<Index>(0, points.rows(), 512, [&](const IndexRange<Index>& range) {
    for (Index i = range.begin(); i < range.end(); ++i) {
      const Eigen::Vector3d p = points.row(i).transpose();
      double best2 = std::numeric_limits<double>::infinity();
      tree.forEachNear(p, best2, [&](int t, double& radius2) {
        const double d2 =
            closestPointOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2)).squaredDistance;
        if (d2 < radius2) radius2 = d2;
      });
      distances[static_cast<std::size_t>(i)] = std::sqrt(best2);
    }
  });
  return distances;
}

std::vector<double> vertexAreaWeights(const SurfaceMesh& mesh) {
  std::vector<double> weights(static_cast<std::size_t>(mesh.vertexCount()), 0.0);
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    const double third = triangleArea(mesh.positions.row(mesh.triangles(t, 0)).transpose(),
                                      mesh.positions.row(mesh.triangles(t, 1)).transpose(),
                                      mesh.positions.row(mesh.triangles(t, 2)).transpose()) /
                         3.0;
    for (int k = 0; k < 3; ++k) weights[static_cast<std::size_t>(mesh.triangles(t, k))] += third;
  }
  return weights;
}

OneSidedDistance oneSidedDistance(const SurfaceMesh& from, const SurfaceMesh& to) {
  const std::vector<double> d = distancesToSurface(from.positions, to);
  const std::vector<double> w = vertexAreaWeights(from);
  std::vector<char> used(d.size(), 0);
  for (Index t = 0; t < from.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(from.triangles(t, k))] = 1;
  OneSidedDistance out;
  double weighted = 0, total = 0, plain = 0;
  Index count = 0;
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (!used[v]) continue;
    if (out.farthestVertex < 0 || d[v] > out.max) {
      out.max = d[v];
      out.farthestVertex = static_cast<Index>(v);
    }
    weighted += w[v] * d[v];
    total += w[v];
    plain += d[v];
    ++count;
  }
  // Every triangle degenerate: no area to weight by, so the plain mean.
  out.mean = total > 0 ? weighted / total : (count > 0 ? plain / static_cast<double>(count) : 0.0);
  return out;
}

}  // namespace tetskin
