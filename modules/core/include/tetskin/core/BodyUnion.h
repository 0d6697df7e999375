// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Several bodies as one: their control meshes side by side in one mesh,
// their skins in one skin and their bindings in one binding, numbered body
// after body. One simulation steps the union (Simulation.h): the bodies
// share no element, so nothing but their contacts couples them.

#include <span>
#include <vector>

#include "tetskin/core/FrameFields.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

// One body: its control mesh (placed), its skin (placed) and the skin's
// binding to the mesh (control ids in the mesh's own numbering).
struct BodyParts {
  const TetMesh* mesh = nullptr;
  const SurfaceMesh* skin = nullptr;
  const SurfaceBinding* binding = nullptr;
};

// Where one body lies in a union: its nodes, elements, skin vertices and
// skin triangles, each [first, first + count).
struct BodyRange {
  Index firstNode = 0, nodeCount = 0;
  Index firstElement = 0, elementCount = 0;
  Index firstVertex = 0, vertexCount = 0;
  Index firstTriangle = 0, triangleCount = 0;
};

struct BodyUnion {
  MultiLevelTetMesh mesh;         // one level: every body's mesh
  SurfaceMesh skin;               // every body's skin
  SurfaceBinding binding;         // of `skin` to `mesh`'s level 0
  std::vector<int> vertexBody;    // per skin vertex, its body (from 0)
  std::vector<BodyRange> bodies;  // in the order given

  int bodyCount() const { return static_cast<int>(bodies.size()); }
};

// The union of `bodies` (at least one; each with a mesh, a skin and a
// binding of the same method). Throws Error naming the body (from 0)
// whose binding does not fit its skin or mesh, or whose method differs
// from the first body's.
BodyUnion uniteBodies(std::span<const BodyParts> bodies);

// `part` (one body's control mesh, its own numbering) written into a
// union's `nodes` and `elements` where `body` says, its elements' node ids
// shifted by the body's first node: bodyPart's inverse.
void placeBodyPart(const TetMesh& part, const BodyRange& body, Points3& nodes,
                   Tetrahedra& elements);

// One body's part of a union, numbered from its own first node and vertex:
// its control mesh, its skin, its skin's binding (control ids and face ids
// less the body's first node and element; unbound slots stay -1), a
// control frame's fields (per node and per element) and per-vertex rows.
TetMesh bodyPart(const TetMesh& united, const BodyRange& body);
SurfaceMesh bodyPart(const SurfaceMesh& united, const BodyRange& body);
SurfaceBinding bodyPart(const SurfaceBinding& united, const BodyRange& body);
FrameFields bodyPart(const FrameFields& united, const BodyRange& body);

}  // namespace tetskin
