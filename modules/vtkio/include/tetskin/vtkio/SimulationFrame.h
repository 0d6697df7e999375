// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One simulated frame of the control mesh as a vtkUnstructuredGrid for
// ParaView: tetrahedra at the deformed positions, point arrays
// Displacement, Velocity, ExternalForce (N per node: loads, scenario
// forces, pulls; not gravity), ReactionForce (N per node: the supports'
// forces at the prescribed nodes, zero elsewhere) and Prescribed (1 where
// the run prescribes the node's motion: held still, or driven as the
// twist's top; else 0),
// cell arrays VonMisesStress, EquivalentStrain, VolumeRatio (current / rest volume, < 0 for
// inverted elements) and Level, and for a run with a floor the field data
// FloorNormal (the up axis' unit vector) and FloorHeight; and the state
// read back from such a frame.

#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

#include "tetskin/core/FrameFields.h"
#include "tetskin/core/RunConditions.h"
#include "tetskin/core/TetMesh.h"

class vtkUnstructuredGrid;

namespace tetskin {

vtkSmartPointer<vtkUnstructuredGrid> simulationFrame(const TetMesh& rest, const FrameFields& fields,
                                                     int level,
                                                     const RunConditions& conditions = {});

// What a simulation restarts from: a frame's positions (its points) and
// velocities (its Velocity array); and, where the frame has them (one
// finite value per tetrahedron; frames written before strains were have no
// EquivalentStrain), its elements' VonMisesStress and EquivalentStrain,
// else empty: what deform carries to the skin of a recorded run.
struct FrameState {
  Points3 positions, velocities;
  Eigen::VectorXd vonMisesStress = {}, equivalentStrain = {};
  SymmetricTensors stress = {};  // empty for a frame without the Stress array
};

// The state in the frame file `path` (a .vtu simulationFrame wrote) of the
// mesh `rest`, named `restName` in messages (e.g. "level 0 of bunny.json").
// Throws Error naming the file when it is no frame of `rest`: other node or
// tetrahedron counts or numbering, points - Displacement not `rest`'s
// positions (to 1e-9 of the largest coordinate), Displacement or Velocity
// missing, or a value not finite.
FrameState readSimulationFrame(const std::filesystem::path& path, const TetMesh& rest,
                               const std::string& restName);

// The rest mesh a frame file was taken from: its tetrahedra, at its points
// less their Displacement. Throws Error naming the file when it is no
// simulation frame (no tetrahedra, no Displacement).
TetMesh readFrameRest(const std::filesystem::path& path);

// What a frame file says of its run: the dataset level it is of (its
// Level cell array), the run's floor (its FloorNormal and FloorHeight),
// each nullopt where the frame does not say (a mesh written by another
// tool, a run without a floor), and its prescribed nodes, sorted (its
// Prescribed array; empty where it has none), and its sizes: points and
// cells.
struct SimulationFrameFacts {
  std::optional<int> level;
  RunConditions conditions;
  Index nodeCount = 0, elementCount = 0;
};
SimulationFrameFacts simulationFrameFacts(const std::filesystem::path& path);

}  // namespace tetskin
