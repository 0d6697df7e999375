// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Several bodies as one: their control meshes side by side in one mesh,
// their skins in one skin and their bindings in one binding, numbered body
// after body. One simulation steps the union (Simulation.h): the bodies
// share no element, so nothing but their contacts couples them.

#include <span>
#include <vector>

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

struct BodyUnion {
  MultiLevelTetMesh mesh;           // one level: every body's mesh
  SurfaceMesh skin;                 // every body's skin
  SurfaceBinding binding;           // of `skin` to `mesh`'s level 0
  std::vector<int> vertexBody;      // per skin vertex, its body (from 0)
  std::vector<Index> firstNode;     // per body, its first node in `mesh`; one more: the count
  std::vector<Index> firstVertex;   // per body, its first skin vertex; one more: the count
  std::vector<Index> firstElement;  // per body, its first element; one more: the count

  int bodyCount() const { return static_cast<int>(firstNode.size()) - 1; }
};

// The union of `bodies` (at least one; each with a mesh, a skin and a
// binding of the same method). Throws Error naming the body (from 0)
// whose binding does not fit its skin or mesh, or whose method differs
// from the first body's.
BodyUnion uniteBodies(std::span<const BodyParts> bodies);

}  // namespace tetskin
