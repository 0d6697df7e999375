// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A control frame's stress and strain on the skin: its elements' von Mises
// stress and equivalent strain carried to a surface bound to its level
// (deformation/SurfaceFields.h), as the point arrays VonMisesStress and
// EquivalentStrain of a surface frame. One wiring for every surface frame
// written: simulate's, the GUI's Record, deform of a recorded run, compare.

#include <Eigen/Core>
#include <vector>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/vtkio/BindingFile.h"

namespace tetskin {

// Per element of a level (`rest`, its own numbering; `firstNode`, its first
// node in the dataset's numbering, which the binding's ids use), `stress`
// and `strain` carried to the surface `binding` binds to that level; each
// left out where it is empty (a recorded frame without it). Throws Error
// for values of another count than the level's elements, or a binding to
// another level's nodes. (The caller's rest mesh: a frame's fields are
// carried without copying the level out of the dataset again.)
std::vector<PointScalars> skinFields(const TetMesh& rest, Index firstNode,
                                     const SurfaceBinding& binding, const Eigen::VectorXd& stress,
                                     const Eigen::VectorXd& strain);

}  // namespace tetskin
