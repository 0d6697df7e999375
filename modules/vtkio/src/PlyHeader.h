// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <filesystem>

namespace tetskin::detail {

// Checks a PLY file's header before VTK's reader sees it: VTK's PLY reader
// crashes on some malformed headers (e.g. a list property on the vertex
// element, assimp's issue623.ply). Throws Error naming file and line.
void checkPlyHeader(const std::filesystem::path& path);

}  // namespace tetskin::detail
