// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// When a moving point passes through a moving triangle over a time step:
// the continuous detection of skins that meet faster than their contact
// shell per step (BodyContact).

#include <Eigen/Core>
#include <array>

namespace tetskin {

// Inputs: a point moving from p0 to p1 over a step, a triangle whose
// corners move from `from` to `to` (each linearly). Output: the time (0 to
// 1) at which the point passes through the triangle from the side its
// counter-clockwise normal points to (outside to inside, for a skin wound
// outward), edges included; 2 when it does not. The time is where the
// point's signed distance to the triangle's plane, taken linearly between
// the step's two ends, is zero, and the crossing is where the point lies
// within the triangle at that time. (Exact detection solves a cubic for
// the coplanar times; over a step a skin turns little, and this misses a
// crossing only where its turn is comparable to the motion.) A degenerate
// triangle is never crossed.
double crossingTime(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                    const std::array<Eigen::Vector3d, 3>& from,
                    const std::array<Eigen::Vector3d, 3>& to);

}  // namespace tetskin
