// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/deformation/SurfaceComparison.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

void surfaceErrors(ConstPoints3Ref positions, ConstPoints3Ref normals,
                   ConstPoints3Ref referencePositions, ConstPoints3Ref referenceNormals,
                   SurfaceErrors& errors) {
  const Index n = positions.rows();
  if (normals.rows() != n || referencePositions.rows() != n || referenceNormals.rows() != n)
    throw Error("surfaces compared: " + std::to_string(n) + " positions, " +
                std::to_string(normals.rows()) + " normals against " +
                std::to_string(referencePositions.rows()) + " and " +
                std::to_string(referenceNormals.rows()) + ": not the same surface");
  errors.distance.resize(n);
  errors.normalAngle.resize(n);
  for (Index v = 0; v < n; ++v) {
    errors.distance[v] = (positions.row(v) - referencePositions.row(v)).norm();
    const Eigen::Vector3d a = normals.row(v), b = referenceNormals.row(v);
    // atan2 of |a x b| and a . b: accurate near 0 and 180 degrees, where
    // acos of the dot product loses half its digits; neither needs unit
    // normals.
    errors.normalAngle[v] = a.squaredNorm() > 0 && b.squaredNorm() > 0
                                ? std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi
                                : 0.0;
  }
}

}  // namespace tetskin
