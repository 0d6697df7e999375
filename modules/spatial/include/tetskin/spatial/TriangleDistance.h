// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Closest point on a triangle to a point (Ericson, Real-Time Collision
// Detection, 5.1.5): exact region classification, so the result is the true
// point-to-triangle distance, not a plane or vertex distance.

#include <Eigen/Core>

namespace tetskin {

struct ClosestPointOnTriangle {
  Eigen::Vector3d point;        // the closest point of the triangle
  Eigen::Vector3d barycentric;  // of `point` with respect to (a, b, c); sums to 1, all >= 0
  double squaredDistance = 0;
};

// Inputs: the point p and the triangle's corners a, b, c. Output: the
// closest point, its barycentric coordinates and the squared distance.
ClosestPointOnTriangle closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The feature of the triangle a closest point lies on, from its
// barycentric coordinates (closestPointOnTriangle's, exact zeros off the
// face): the face, an edge (the one opposite `corner`), or a corner. The
// pseudo-normal of that feature (the face's normal, the sum of the edge's
// two faces', the corner's faces' weighted by their angles there) tells
// the side of a closed surface a point lies on (Baerentzen and Aanaes
// 2005).
struct TriangleFeature {
  enum Kind { Face, Edge, Corner } kind = Face;
  int corner = -1;  // Edge: the corner opposite it; Corner: the corner
};
TriangleFeature closestFeature(const Eigen::Vector3d& barycentric);

// Barycentric coordinates of the projection of p onto the plane of (a, b, c):
// unclamped (negative outside the triangle); NaN-free only for non-degenerate
// triangles, so callers check the area first.
Eigen::Vector3d planeBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace tetskin
