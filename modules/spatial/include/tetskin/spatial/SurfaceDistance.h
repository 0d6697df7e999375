// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How far one surface lies from another: the exact distance from points to
// the nearest point of a triangle surface (AABB tree over its triangles,
// closestPointOnTriangle), and the one-sided distance of a whole surface
// from another, sampled at its vertices. What `build --wrap` reports of a
// wrap against its input, in both directions.

#include <span>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// Inputs: #P x 3 points; a surface of #V x 3 positions and #F >= 1
// triangles (degenerate ones included: their closest point is on their
// edges). Output: #P distances (model units), exact. Threaded.
std::vector<double> distancesToSurface(const Points3& points, const SurfaceMesh& surface);

// A one-sided distance from surface A to surface B, over A's vertices:
// the largest, and the mean weighted by each vertex's share of A's area (a
// third of its triangles' areas), so a finely meshed patch does not
// outweigh a coarse one. Vertices that no triangle uses are left out.
struct OneSidedDistance {
  double max = 0;
  double mean = 0;
  Index farthestVertex = -1;  // of A, where `max` is reached
};
OneSidedDistance oneSidedDistance(const SurfaceMesh& from, const SurfaceMesh& to);

// The per-vertex area weights used above: a third of the area of each
// triangle a vertex belongs to.
std::vector<double> vertexAreaWeights(const SurfaceMesh& mesh);

}  // namespace tetskin
