// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// MEDIT's ASCII mesh format (.mesh, INRIA; what CGAL's 3D mesher, fTetWild
// and MMG write): keyword sections of vertices, triangles and tetrahedra,
// each record ending in a reference number. Indices count from 1.
// https://www.ljll.fr/frey/publications/RT-0253.pdf (the format's report)

#include <filesystem>
#include <string>
#include <string_view>

#include "tetskin/core/TetMesh.h"
#include "tetskin/core/Types.h"

namespace tetskin {

struct MeditMesh {
  Points3 vertices;
  Triangles triangles;    // 0-based, as listed (references dropped)
  Tetrahedra tetrahedra;  // 0-based, as listed (references dropped)
  // Records of the sections read past: edges, quadrilaterals, corners,
  // ridges, required entities, normals and tangents.
  Index skippedRecords = 0;
};

// Throws Error naming the file and line: a missing or unknown keyword
// (with the ones this reader takes), a dimension other than 3, a count the
// rest of the file cannot hold, a record cut short, a non-finite
// coordinate, an index out of range, hexahedra, prisms or pyramids (a
// dataset is made of tetrahedra).
MeditMesh readMedit(const std::filesystem::path& path);
// The same of a file's content, named `sourceName` in errors.
MeditMesh parseMedit(std::string_view content, const std::string& sourceName);

// Writes MeshVersionFormatted 2 (double precision), Dimension 3, the
// sections that are not empty, End; atomically.
void writeMedit(const std::filesystem::path& path, const MeditMesh& mesh);

}  // namespace tetskin
