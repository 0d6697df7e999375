// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One simulated frame of a control level as it is exported: per node (the
// level's numbering) the positions, velocities, the external forces of the
// step that led to it (loads, scenario forces, pulls; not gravity) and the
// supports' reactions (at the prescribed nodes, zero elsewhere), both in
// newtons; per element the stress tensor and its von Mises stress (Pa) and
// the equivalent strain (CorotatedFem::elementMeasures).
// Simulation::frameFields() takes them at one instant; the .vtu frames
// carry them.

#include <Eigen/Core>

#include "tetskin/core/Types.h"

namespace tetskin {

// Symmetric tensors, one per row, in VTK's order of six: xx, yy, zz, xy,
// yz, xz.
using SymmetricTensors = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

struct FrameFields {
  Points3 positions, velocities, externalForces, reactionForces;
  Eigen::VectorXd vonMisesStress, equivalentStrain;
  // Per node, N: the floor's and obstacles' forces (Simulation::
  // contactForces); empty for a run without contact.
  Points3 contactForces = {};
  // Per element, Pa: the stress tensor in the world's axes (empty: not
  // known, as in frames read back from files that lack it).
  SymmetricTensors stress = {};
};

}  // namespace tetskin
