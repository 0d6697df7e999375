// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Basic geometry on points, triangles and tetrahedra.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

struct BoundingBox {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return (min.array() > max.array()).any(); }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  Eigen::Vector3d extent() const { return max - min; }
  // Length of the diagonal; 0 for an empty box.
  double diagonal() const { return empty() ? 0.0 : extent().norm(); }
  void extend(const Eigen::Vector3d& p);
};

// Axis-aligned bounding box of #P x 3 points; empty for no rows.
BoundingBox boundingBox(const Points3& points);

// The volume two boxes share over the volume they span together (their
// union): 1 for equal boxes, 0 for disjoint ones (and for an empty one, or
// flat ones that differ).
double boxOverlap(const BoundingBox& a, const BoundingBox& b);

// The rows of `points` inside `box` (its faces included), in order.
std::vector<int> pointsInBox(const Points3& points, const BoundingBox& box);

// Three numbers as the command line takes them and messages show them
// (formatNumber each): "0,-9.81,0".
std::string commaSeparated(const Eigen::Vector3d& v);

// Row of `points` nearest to `query` (the lowest on ties); -1 when empty.
Index nearestPoint(const Points3& points, const Eigen::Vector3d& query);

// Signed volume of the tetrahedron (a, b, c, d): positive when d lies on the
// side of triangle (a, b, c) that its counter-clockwise normal points away
// from, i.e. (b-a) x (c-a) . (d-a) > 0 (TetGen's orientation).
double signedTetVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& d);

// (b-a) x (c-a) / 2: normal direction times area.
Eigen::Vector3d triangleAreaVector(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c);
double triangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);
// Unit normal (counter-clockwise winding); the zero vector for a degenerate triangle.
Eigen::Vector3d triangleNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);
// The angle of triangle (a, b, c) at a, in radians (a pseudo-normal's weight).
double triangleAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The largest coordinate magnitude a mesh may have. Areas, volumes and
// TetGen's predicates multiply up to five coordinate differences, which
// must stay finite in double precision; beyond this a model is almost
// surely in the wrong units (or corrupt) and should be rescaled.
inline constexpr double kMaxCoordinate = 1e30;

// What is wrong with a point's coordinates, as the end of a sentence that
// names the point ("has a non-finite coordinate", "has a coordinate ...
// beyond +-1e30 ..."); empty when they are finite and within kMaxCoordinate.
std::string coordinateProblem(const Eigen::Ref<const Eigen::RowVector3d>& point);

}  // namespace tetskin
