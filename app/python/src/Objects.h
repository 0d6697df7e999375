// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the module's Python objects hold: the libraries' own types, shared
// where several objects need one (a dataset outlives every level, binding
// and simulation made from it, whatever Python releases first).

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "tetskin/core/TetMesh.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/vtkio/BindingFile.h"

namespace tetskin::python {

struct DatasetObject {
  std::shared_ptr<const Dataset> dataset;
  std::filesystem::path path;  // as given (names the dataset in errors and bindings)
};

// One level, in its own numbering (node ids from 0).
struct LevelObject {
  std::shared_ptr<const Dataset> dataset;
  int index = 0;
  TetMesh mesh;
  Triangles boundaryFaces;
};

struct BindingObject {
  std::shared_ptr<const Dataset> dataset;
  BoundSurface bound;  // bound.dataset: the dataset's path
  // Made at the first deform and kept (it packs the binding for the
  // per-frame kernel); `deforming` serializes deforms of one binding.
  std::unique_ptr<SurfaceDeformer> deformer;
  std::mutex deforming;

  // The deformer, made on first use (with `deforming` held).
  SurfaceDeformer& madeDeformer() {
    if (!deformer)
      deformer = std::make_unique<SurfaceDeformer>(bound.surface, bound.binding,
                                                   dataset->mesh.nodes, "binding");
    return *deformer;
  }
};

struct SimulationObject {
  std::shared_ptr<const Dataset> dataset;
  std::unique_ptr<SimulationSession> session;
  RunSpec spec;    // what the session was made from (run_spec)
  Points3 forces;  // apply_forces(): per level node, added to the scenario's each step
  bool forcesGiven = false;
  int recordEvery = 1;
  // Held by a step and by whatever changes the run (Simulation allows
  // reading its state during a step, not changing it).
  std::mutex changing;

  Index nodeCount() const { return session->simulation().restMesh().nodeCount(); }
  std::string levelWords() const {
    return "level " + std::to_string(session->level()) + " (" + std::to_string(nodeCount()) +
           " nodes)";
  }
};

// The run's warnings not shown yet, as Python UserWarnings.
void warnOfRun(SimulationObject& s);

}  // namespace tetskin::python
