// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/fur/FurDynamics.h"

namespace tetskin {

Eigen::Vector3d furShellOffset(const Eigen::Vector3d& n, const Eigen::Vector3d& velocity, double h,
                               double length, const FurDynamicsOptions& o) {
  const double rise = h * length;
  Eigen::Vector3d shift = -o.drag * h * h * velocity;
  const double norm = shift.norm();
  const double bound = o.maxBend * rise;
  if (norm > bound) shift *= bound / norm;
  const double lift = rise + shift.dot(n);
  if (lift < o.minLift * rise) shift += (o.minLift * rise - lift) * n;
  return rise * n + shift;
}

void furVelocities(const Points3& previous, const ConstPoints3Ref& current, double seconds,
                   Points3& out) {
  out.setZero(current.rows(), 3);
  if (seconds <= 0 || previous.rows() != current.rows()) return;
  out = (current - previous) / seconds;
}

}  // namespace tetskin
