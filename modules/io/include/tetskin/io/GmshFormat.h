// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The tetrahedra of a Gmsh volume mesh (.msh, ASCII, format versions 2.2
// and 4.1: https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format), for
// `tetskin convert` to make a dataset of, as of a .vtu made elsewhere.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/TetMesh.h"

namespace tetskin {

struct GmshTetrahedra {
  // Every node of the file, in the order $Nodes lists them, and the
  // tetrahedra's corner nodes (a quadratic tetrahedron's first four).
  TetMesh mesh;
  // The elements of dimension 0 to 2 the file carries besides (boundary
  // triangles, edges, points), left out.
  Index skippedElements = 0;
  // Each tetrahedron's element tag in the file, for messages.
  std::vector<long long> elementTags;
};

// Throws Error naming the file and line: a binary file or another format
// version (with what to save instead), a malformed or truncated section,
// a node tag listed twice or missing, an element with the wrong number of
// nodes, a three-dimensional element other than a tetrahedron (a hexahedron,
// prism or pyramid), an element type this reader does not know, and a
// file without tetrahedra.
GmshTetrahedra readGmshTetrahedra(const std::filesystem::path& path);
// The same of a file's content, named `sourceName` in errors.
GmshTetrahedra parseGmshTetrahedra(std::string_view content, const std::string& sourceName);

}  // namespace tetskin
