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

// Per element of `level` of `dataset`, `stress` and `strain` carried to the
// surface `binding` binds to that level; each left out where it is empty
// (a recorded frame without it). Throws Error for values of another count
// than the level's elements, or a binding to another level's nodes.
std::vector<PointScalars> skinFields(const MultiLevelTetMesh& dataset, int level,
                                     const SurfaceBinding& binding, const Eigen::VectorXd& stress,
                                     const Eigen::VectorXd& strain);

}  // namespace tetskin
