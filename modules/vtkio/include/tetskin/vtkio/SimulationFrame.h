// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One simulated frame of the control mesh as a vtkUnstructuredGrid for
// ParaView: tetrahedra at the deformed positions, point arrays
// Displacement, Velocity and ExternalForce (N per node: loads, scenario
// forces, pulls; not gravity), cell arrays VonMisesStress, VolumeRatio
// (current / rest volume, < 0 for inverted elements) and Level.

#include <vtkSmartPointer.h>

#include <Eigen/Core>

#include "tetskin/core/TetMesh.h"

class vtkUnstructuredGrid;

namespace tetskin {

vtkSmartPointer<vtkUnstructuredGrid> simulationFrame(const TetMesh& rest, const Points3& positions,
                                                     const Points3& velocities,
                                                     const Points3& externalForces,
                                                     const Eigen::VectorXd& vonMisesStress,
                                                     int level);

}  // namespace tetskin
