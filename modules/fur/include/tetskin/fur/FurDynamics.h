// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Dynamic fur (report section 5): the shells trail the motion of the skin.
// A shell point at height h (0 root .. 1 tip) above a skin point with unit
// normal n, moving with velocity v, sits at
//     h L n + s,   s = -drag v h^2
// (little shift at the root, more with height), with |s| bounded by
// maxBend h L and the lift above the skin kept at least minLift h L, so fur
// never sinks into the base surface whatever the velocity. The GLSL of the
// fur-gpu path (shaders/fur_shell_impl.vs.glsl) computes the same formula.

#include "tetskin/core/Types.h"

namespace tetskin {

struct FurDynamicsOptions {
  double drag = 0.04;     // seconds; 0 = static fur
  double maxBend = 0.6;   // largest shift, in h L
  double minLift = 0.35;  // smallest height above the skin, in h L
};

Eigen::Vector3d furShellOffset(const Eigen::Vector3d& unitNormal, const Eigen::Vector3d& velocity,
                               double height, double length, const FurDynamicsOptions& options);

// (current - previous) / seconds, row by row (resizes `out`); zero when
// seconds <= 0 or the shapes differ (the first frame).
void furVelocities(const Points3& previous, const ConstPoints3Ref& current, double seconds,
                   Points3& out);

}  // namespace tetskin
