// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The benchmarks' CGAL baseline: the closest-point query a geometry
// researcher would reach for, CGAL's AABB tree over a surface's triangles
// (accelerate_distance_queries): binding_bench binds with it (the nearest
// triangle's plane barycentric weights: no ties, offsets or diagnostics),
// contact_bench measures the obstacle's distance queries against it.

#include <memory>
#include <utility>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::bench {

class CgalTriangleTree {
 public:
  // Over `surface`'s triangles (built, distance queries accelerated, before
  // any query: queries are then const and may run on every core).
  explicit CgalTriangleTree(const SurfaceMesh& surface);
  ~CgalTriangleTree();
  // The closest point of the surface to p, and its triangle.
  std::pair<Eigen::Vector3d, Index> closest(const Eigen::Vector3d& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

SurfaceBinding bindWithCgal(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level);

}  // namespace tetskin::bench
