// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// binding_bench's CGAL baseline: the closest-point query a geometry
// researcher would reach for, CGAL's AABB tree over the level's boundary
// triangles (accelerate_distance_queries), one closest_point_and_primitive
// per vertex on every core, then the closest triangle's plane barycentric
// weights: the nearest triangle and its weights, no ties, offsets or
// diagnostics.

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::bench {

SurfaceBinding bindWithCgal(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level);

}  // namespace tetskin::bench
