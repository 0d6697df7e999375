// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Wavefront OBJ surfaces.
//
// Reads `v`, `vt`, `vn` and `f` (corners `v`, `v/vt`, `v//vn`, `v/vt/vn`,
// negative indices counting back from the last element read), triangulates
// polygons as fans, tolerates comments, CRLF, a missing final newline and the
// statements that carry no geometry TetSkin uses (`o`, `g`, `s`, `usemtl`,
// `mtllib`, `l`, `p`, ...). Anything else (an unknown statement, a non-number,
// an index out of range, binary data) is an Error naming file and line.

#include <filesystem>
#include <string>
#include <string_view>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

struct ObjReadOptions {
  // Keep `vt`/`vn` as per-vertex attributes. A position used with different
  // texture coordinates or normals at different corners (a seam) is then split
  // into one vertex per distinct combination. An attribute is kept only when
  // every face corner has one.
  bool keepAttributes = true;
};

SurfaceMesh readObj(const std::filesystem::path& path, const ObjReadOptions& options = {});
// `sourceName` is used in error messages.
SurfaceMesh parseObj(std::string_view content, const std::string& sourceName,
                     const ObjReadOptions& options = {});

// Writes positions, texture coordinates and normals when present, 1-based.
void writeObj(const std::filesystem::path& path, const SurfaceMesh& mesh);

}  // namespace tetskin
