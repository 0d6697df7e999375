// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Tetrahedral meshes made elsewhere, by file extension: Gmsh .msh (ASCII or
// binary, 2.2 and 4.1), MEDIT .mesh, a TetGen .node/.ele pair. The one
// place that knows them: a one-level dataset (Dataset.h), `convert`'s import
// and `info` all read through it. (A .vtu goes through vtkio.)

#include <filesystem>
#include <string>
#include <vector>

#include "tetskin/core/TetMesh.h"

namespace tetskin {

struct TetrahedraFile {
  TetMesh mesh;  // every node the file lists, the tetrahedra in file order
  // Elements of lower dimension (triangles, edges, points) left out.
  Index skippedElements = 0;
  std::string format;  // "Gmsh", "MEDIT" or "TetGen"
  // How the file numbers each tetrahedron, for messages: "element 7" (a
  // Gmsh tag, a TetGen element number), "tetrahedron 3" (MEDIT's record).
  std::vector<long long> numbers;
  std::string elementName(Index e) const;
};

// Whether readTetrahedraFile takes the file by its extension (any letter
// case): .msh, .mesh, .node, .ele.
bool isTetrahedraFile(const std::filesystem::path& path);

// Throws Error naming the file (and line, record or byte) for what its
// reader refuses, and for a file without tetrahedra.
TetrahedraFile readTetrahedraFile(const std::filesystem::path& path);

}  // namespace tetskin
