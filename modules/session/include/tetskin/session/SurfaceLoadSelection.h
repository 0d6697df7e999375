// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A surface load as a user asks for it (the CLI's --pressure, --traction,
// --load-box and --load-faces; a scene body's surface_loads; Python's
// keywords), and the faces of the level's boundary it selects: those whose
// corners all lie in a box, or those a face set names.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin {

struct SurfaceLoadRequest {
  std::string name = "the surface load";  // names it in errors ("/bodies/0/surface_loads/1")
  double pressure = 0;                    // Pa
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();  // Pa
  // Exactly one of the three selects the faces: a box, a face-set file
  // (io NodeList.h), or faces given as node triples.
  std::optional<BoundingBox> box;
  std::filesystem::path faceFile;
  Triangles faceNodes;
  // The body the load is on (a scene's body within the run's level): its
  // faces are chosen among this body's, and node ids of a face set count
  // from its first node. nodeCount < 0: the whole level.
  Index firstNode = 0;
  Index nodeCount = -1;
};

// The surface load `request` asks for on `level` (node ids the level's,
// faces wound outward). Throws Error naming request.name for a box that
// holds no boundary face of the body (naming the body's extent), a face
// that is not on its boundary (naming the file and line, or the row), a
// face given twice, a request with no or two face selections, and a
// pressure or traction that is not finite.
SurfaceLoad selectSurfaceLoad(const SurfaceLoadRequest& request, const TetMesh& level);

}  // namespace tetskin
