// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Stanford PLY surfaces, ascii and binary (either byte order).
//
// Reads the `vertex` element's x, y, z (and nx, ny, nz and u, v, s, t,
// texture_u/v or texture_s/t where present) and the `face` element's
// `vertex_indices` (or `vertex_index`) lists, polygons triangulated as fans;
// other properties and elements are read past. Everything is checked as it
// is read: a truncated file, a count that the rest of the file cannot hold,
// an index out of range, a face of fewer than 3 vertices, a non-finite or
// out-of-range coordinate are Errors naming the file and the line (ascii)
// or the element (binary), never a crash or a huge allocation.

#include <filesystem>
#include <string>
#include <string_view>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

SurfaceMesh readPly(const std::filesystem::path& path);
// `sourceName` is used in error messages.
SurfaceMesh parsePly(std::string_view content, const std::string& sourceName);

// Binary little-endian; positions, normals and texture coordinates (u, v) as
// doubles, so a surface reads back exactly.
void writePly(const std::filesystem::path& path, const SurfaceMesh& mesh);

}  // namespace tetskin
