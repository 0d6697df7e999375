// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Axis-aligned box used by the spatial search structures.

#include <Eigen/Core>
#include <limits>

namespace tetskin {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Aabb& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  Aabb inflated(double margin) const { return {min.array() - margin, max.array() + margin}; }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  bool overlaps(const Aabb& b) const {
    return (min.array() <= b.max.array()).all() && (b.min.array() <= max.array()).all();
  }
  bool contains(const Eigen::Vector3d& p) const {
    return (min.array() <= p.array()).all() && (p.array() <= max.array()).all();
  }
  // Squared distance from p to the box (0 inside).
  double squaredDistance(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = (min - p).cwiseMax(p - max).cwiseMax(0.0);
    return d.squaredNorm();
  }
};

}  // namespace tetskin
