// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/PathCrossing.h"

#include <Eigen/Geometry>

#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {

double crossingTime(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                    const std::array<Eigen::Vector3d, 3>& from,
                    const std::array<Eigen::Vector3d, 3>& to) {
  const Eigen::Vector3d n0 = (from[1] - from[0]).cross(from[2] - from[0]).normalized();
  const Eigen::Vector3d n1 = (to[1] - to[0]).cross(to[2] - to[0]).normalized();
  const double s0 = n0.dot(p0 - from[0]), s1 = n1.dot(p1 - to[0]);
  if (!(s0 > 0 && s1 < 0)) return 2;  // (NaN for a degenerate triangle: no crossing)
  const double t = s0 / (s0 - s1);
  const auto at = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return ((1 - t) * a + t * b).eval();
  };
  const Eigen::Vector3d w =
      planeBarycentric(at(p0, p1), at(from[0], to[0]), at(from[1], to[1]), at(from[2], to[2]));
  constexpr double kEdge = -1e-9;  // on an edge counts: the next triangle may round it out
  return w.minCoeff() >= kEdge ? t : 2;
}

}  // namespace tetskin
