// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The signed distance to a closed triangle surface (an obstacle): the exact
// closest point (AABB tree over the triangles, closestPointOnTriangle) and
// the side, from the angle-weighted pseudo-normal of the face, edge or
// vertex the closest point lies on (Baerentzen and Aanaes 2005), which is
// exact for a closed, consistently wound surface. Queries are const and
// thread-safe; a bounded query (`radius`) visits only the nearby part of
// the tree, which is what keeps contact detection cheap.

#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/spatial/AabbTree.h"

namespace tetskin {

struct SurfacePoint {
  double distance = 0;     // signed, model units: negative inside
  Eigen::Vector3d point;   // the closest point of the surface
  Eigen::Vector3d normal;  // unit, outward: along p - point (away from the
                           // surface when outside), the pseudo-normal at 0
  Index triangle = -1;     // the closest point's triangle
};

class ClosedSurfaceDistance {
 public:
  // Input: a closed surface, every edge shared by exactly two triangles
  // wound in opposite directions (a surface wound inward is turned
  // outward). Throws Error naming `name` and the first open or
  // inconsistently wound edge, or the first degenerate triangle.
  ClosedSurfaceDistance(SurfaceMesh surface, const std::string& name);

  const SurfaceMesh& surface() const { return surface_; }
  const Aabb& bounds() const { return tree_.bounds(); }

  // The closest point of the surface to p and the side p lies on; nullopt
  // when the surface lies farther than `radius` from p.
  std::optional<SurfacePoint> closest(
      const Eigen::Vector3d& p, double radius = std::numeric_limits<double>::infinity()) const;

 private:
  Eigen::Vector3d corner(Index t, int k) const {
    return surface_.positions.row(surface_.triangles(t, k)).transpose();
  }

  SurfaceMesh surface_;
  AabbTree tree_;
  std::vector<Eigen::Vector3d> faceNormals_;    // per triangle
  std::vector<Eigen::Vector3d> vertexNormals_;  // angle-weighted, per vertex
  std::vector<Eigen::Vector3d> edgeNormals_;    // per triangle and edge k (opposite corner k)
};

}  // namespace tetskin
