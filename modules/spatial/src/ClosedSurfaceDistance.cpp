// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/ClosedSurfaceDistance.h"

#include <Eigen/Geometry>
#include <cmath>
#include <unordered_map>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {

ClosedSurfaceDistance::ClosedSurfaceDistance(SurfaceMesh surface, const std::string& name)
    : surface_(std::move(surface)) {
  validateSurface(surface_, name);
  const Index triangles = surface_.triangleCount();
  if (triangles == 0)
    throw Error(name + ": an obstacle needs a closed surface, found no triangles");
  // Each undirected edge: the triangles on it, and the sum of the
  // directions they run it in (+1 a->b with a < b, -1 b->a): a closed,
  // consistently wound surface has two triangles and a sum of 0 on each.
  struct EdgeUse {
    int count = 0, direction = 0;
    Eigen::Vector3d normalSum = Eigen::Vector3d::Zero();
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(static_cast<std::size_t>(3 * triangles));
  const auto edgeKey = [&](Index t, int k) {
    const auto a = static_cast<std::uint64_t>(surface_.triangles(t, (k + 1) % 3));
    const auto b = static_cast<std::uint64_t>(surface_.triangles(t, (k + 2) % 3));
    return std::pair{std::min(a, b) << 32 | std::max(a, b), a < b ? 1 : -1};
  };
  if (enclosedVolume(surface_) < 0) surface_.triangles.col(1).swap(surface_.triangles.col(2));
  faceNormals_.resize(static_cast<std::size_t>(triangles));
  vertexNormals_.assign(static_cast<std::size_t>(surface_.vertexCount()), Eigen::Vector3d::Zero());
  std::vector<Aabb> boxes(static_cast<std::size_t>(triangles));
  for (Index t = 0; t < triangles; ++t) {
    const Eigen::Vector3d n = triangleNormal(corner(t, 0), corner(t, 1), corner(t, 2));
    if (n.isZero())
      throw Error(name + ": triangle " + std::to_string(t) +
                  " has zero area; an obstacle's side is undefined there");
    faceNormals_[static_cast<std::size_t>(t)] = n;
    for (int k = 0; k < 3; ++k) {
      boxes[static_cast<std::size_t>(t)].extend(corner(t, k));
      vertexNormals_[static_cast<std::size_t>(surface_.triangles(t, k))] +=
          triangleAngle(corner(t, k), corner(t, (k + 1) % 3), corner(t, (k + 2) % 3)) * n;
      const auto [key, direction] = edgeKey(t, k);
      EdgeUse& use = edges[key];
      ++use.count;
      use.direction += direction;
      use.normalSum += n;
    }
  }
  edgeNormals_.resize(static_cast<std::size_t>(3 * triangles));
  for (Index t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const EdgeUse& use = edges.at(edgeKey(t, k).first);
      if (use.count != 2 || use.direction != 0)
        throw Error(name + ": the edge " + std::to_string(surface_.triangles(t, (k + 1) % 3)) +
                    "-" + std::to_string(surface_.triangles(t, (k + 2) % 3)) + " of triangle " +
                    std::to_string(t) +
                    (use.count != 2 ? " is in " + std::to_string(use.count) +
                                          (use.count == 1 ? " triangle" : " triangles") +
                                          "; an obstacle must be a closed surface (every "
                                          "edge in two triangles)"
                                    : " is run in the same direction by both its triangles; an "
                                      "obstacle's triangles must be wound consistently"));
      edgeNormals_[static_cast<std::size_t>(3 * t + k)] = use.normalSum.normalized();
    }
  for (Eigen::Vector3d& n : vertexNormals_) n.normalize();
  tree_ = AabbTree(boxes);
}

std::optional<SurfacePoint> ClosedSurfaceDistance::closest(const Eigen::Vector3d& p,
                                                           double radius) const {
  double best2 = radius * radius;
  Index bestTriangle = -1;
  ClosestPointOnTriangle best;
  tree_.forEachNear(p, best2, [&](int t, double& radius2) {
    const ClosestPointOnTriangle c =
        closestPointOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
    if (c.squaredDistance <= radius2 &&
        (bestTriangle < 0 || c.squaredDistance < best.squaredDistance)) {
      radius2 = c.squaredDistance;
      best = c;
      bestTriangle = t;
    }
  });
  if (bestTriangle < 0) return std::nullopt;
  const auto t = static_cast<std::size_t>(bestTriangle);
  const TriangleFeature feature = closestFeature(best.barycentric);
  const Eigen::Vector3d& pseudoNormal =
      feature.kind == TriangleFeature::Corner
          ? vertexNormals_[static_cast<std::size_t>(
                surface_.triangles(bestTriangle, feature.corner))]
      : feature.kind == TriangleFeature::Edge
          ? edgeNormals_[3 * t + static_cast<std::size_t>(feature.corner)]
          : faceNormals_[t];
  SurfacePoint out;
  out.point = best.point;
  out.triangle = bestTriangle;
  const Eigen::Vector3d away = p - best.point;
  const double side = away.dot(pseudoNormal) >= 0 ? 1.0 : -1.0;
  const double length = std::sqrt(best.squaredDistance);
  out.distance = side * length;
  out.normal = length > 0 ? Eigen::Vector3d(side * away / length) : pseudoNormal;
  return out;
}

}  // namespace tetskin
