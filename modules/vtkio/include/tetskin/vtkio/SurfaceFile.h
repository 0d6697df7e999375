// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Surface files by extension: .obj and .ply (TetSkin's strict readers, in
// io), .stl and .vtp (VTK's readers, with their errors turned into
// tetskin::Error).

#include <filesystem>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

SurfaceMesh readSurface(const std::filesystem::path& path);
// Writes .obj, .ply, .stl or .vtp atomically.
void writeSurface(const std::filesystem::path& path, const SurfaceMesh& mesh);

// Whether readSurface knows the file's extension.
bool isSurfaceFile(const std::filesystem::path& path);

}  // namespace tetskin
