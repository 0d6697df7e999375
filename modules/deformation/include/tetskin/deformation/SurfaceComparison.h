// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Two deformations of the same surface (its vertices and triangles, bound
// to two control levels) compared vertex by vertex: how far apart each
// vertex lies and the angle between its normals. The fidelity of a coarse
// control level against a finer one (`tetskin compare`, the GUI's Compare).

#include <Eigen/Core>

#include "tetskin/core/Types.h"

namespace tetskin {

struct SurfaceErrors {
  Eigen::VectorXd distance;     // |x - x_ref|, model units
  Eigen::VectorXd normalAngle;  // degrees, in [0, 180]; 0 where either normal is zero
};

// Inputs: #V x 3 positions and normals, and the reference's #V x 3
// positions and normals (model units; normals of any length).
// Outputs: `errors`, #V distances (model units) and #V angles (degrees),
// resized when its size differs. Throws Error when the four do not have
// the same rows.
void surfaceErrors(ConstPoints3Ref positions, ConstPoints3Ref normals,
                   ConstPoints3Ref referencePositions, ConstPoints3Ref referenceNormals,
                   SurfaceErrors& errors);

}  // namespace tetskin
