// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A scene (SceneFile.h) made ready to run, the same for every front end:
// its body's dataset and surface placed by the body's transform, the
// surface bound to the level (or its binding checked), the obstacles'
// surfaces read and checked closed, and the run request the scene
// describes. Several bodies become one (BodyUnion.h): their levels one
// single-level dataset, their skins one surface (a body without a surface
// gets its level's boundary as its skin), and the request's bodies say
// where each lies, with its material, velocity and self-contact; each
// body's held nodes and loads are the request's, numbered in the union. A front end overrides the
// scene's values by its own (flags, keywords) on the Scene before loading (the body's level and
// surface) or on the request after (the time step, the material, ...).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/session/SceneFile.h"

namespace tetskin {

struct SceneSurface {
  std::filesystem::path path;
  SurfaceMesh surface;     // placed
  SurfaceBinding binding;  // to the run's level of the placed dataset
};

struct SceneRun {
  Scene scene;
  Dataset dataset;  // placed by the body's transform (every level); several: their union
  int level = 0;    // resolved
  std::optional<SceneSurface> surface;
  RunRequest request;  // the scene's run; errors name its keys
  int steps = 0;       // the scene's, else recording_option::kSteps' default
};

// Loads what `scene` names and makes its run. Throws Error naming the
// scene file and the field for a file that is missing or unreadable, an
// obstacle that is not closed, a binding of another level than the
// body's, or a held box around no node; with several bodies also for a
// body whose scenario is not free, whose contact points or load curve are
// not the first's, or whose skin is bound by another method.
SceneRun loadScene(const Scene& scene);

// The shape of an obstacle read from a surface file (OBJ, PLY, STL, VTP),
// checked closed. Throws Error naming the file.
std::shared_ptr<const ClosedSurfaceDistance> readObstacleShape(const std::filesystem::path& path);

// `mesh`, `surface` and `binding` moved by `placement` (the binding's
// offsets scale with it; its weights stay).
void place(const ScenePlacement& placement, MultiLevelTetMesh& mesh);
void place(const ScenePlacement& placement, SurfaceMesh& surface);
void place(const ScenePlacement& placement, SurfaceBinding& binding);

}  // namespace tetskin
