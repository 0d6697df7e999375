// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Orientation tests whose signs are exact for any double coordinates
// (Shewchuk's adaptive predicates, as TetGen ships them). A plain
// floating-point sign is wrong where the answer is near 0: on the flat faces
// of a CAD model, split into many triangles and turned off the axes, it took
// neighbours for intersecting triangles.

#include <Eigen/Core>

namespace tetskin {

// Sign of (b - a) x (c - a) . (d - a): +1 where d lies on the side of plane
// abc its counter-clockwise normal points to, 0 on the plane.
int orientation3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d);

// Sign of (b - a) x (c - a): +1 for a counter-clockwise turn, 0 collinear.
int orientation2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace tetskin
