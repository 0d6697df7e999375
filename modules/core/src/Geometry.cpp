// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/Geometry.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"

namespace tetskin {

void BoundingBox::extend(const Eigen::Vector3d& p) {
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

BoundingBox boundingBox(const Points3& points) {
  BoundingBox box;
  if (points.rows() == 0) return box;
  box.min = points.colwise().minCoeff().transpose();
  box.max = points.colwise().maxCoeff().transpose();
  return box;
}

std::vector<int> pointsInBox(const Points3& points, const BoundingBox& box) {
  std::vector<int> inside;
  for (Index i = 0; i < points.rows(); ++i)
    if ((points.row(i).transpose().array() >= box.min.array()).all() &&
        (points.row(i).transpose().array() <= box.max.array()).all())
      inside.push_back(static_cast<int>(i));
  return inside;
}

std::string commaSeparated(const Eigen::Vector3d& v) {
  return formatNumber(v.x()) + "," + formatNumber(v.y()) + "," + formatNumber(v.z());
}

double boxOverlap(const BoundingBox& a, const BoundingBox& b) {
  if (a.empty() || b.empty()) return 0.0;
  const double shared = (a.max.cwiseMin(b.max) - a.min.cwiseMax(b.min)).cwiseMax(0.0).prod();
  const double together = a.extent().prod() + b.extent().prod() - shared;
  if (!(together > 0)) return a.min == b.min && a.max == b.max ? 1.0 : 0.0;
  return shared / together;
}

double signedTetVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                       const Eigen::Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

Eigen::Vector3d triangleAreaVector(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a);
}

double triangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return triangleAreaVector(a, b, c).norm();
}

Eigen::Vector3d triangleNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return Eigen::Vector3d::Zero();
  return n / length;
}

double triangleAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  // atan2 of |u x v| and u . v: accurate near 0 and 180 degrees.
  const Eigen::Vector3d u = b - a, v = c - a;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

Index nearestPoint(const Points3& points, const Eigen::Vector3d& query) {
  Index best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < points.rows(); ++i) {
    const double d = (points.row(i).transpose() - query).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  }
  return best;
}

std::string coordinateProblem(const Eigen::Ref<const Eigen::RowVector3d>& point) {
  if (!point.allFinite()) return "has a non-finite coordinate";
  const double largest = point.cwiseAbs().maxCoeff();
  if (largest <= kMaxCoordinate) return {};
  return "has a coordinate of magnitude " + formatNumber(largest) +
         ", beyond the largest accepted (" + formatNumber(kMaxCoordinate) + "); rescale the model";
}

}  // namespace tetskin
