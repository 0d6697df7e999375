// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Atomic VTK XML writers (.vtp, .vtu) and checked readers, for exports that
// ParaView opens; PNG images (screenshots, textures).

#include <vtkSmartPointer.h>

#include <filesystem>

class vtkImageData;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace tetskin {

void writeVtp(const std::filesystem::path& path, vtkPolyData* data);
void writeVtu(const std::filesystem::path& path, vtkUnstructuredGrid* data);
// A .vtp, or a .pvtp read whole (readPvtp).
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path);
vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& path);
void writePng(const std::filesystem::path& path, vtkImageData* image);
// An 8-bit RGB or RGBA image (grey and palette images become RGB), rows
// bottom-up as VTK's; throws Error naming the file for anything else or a
// damaged file.
vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path);

}  // namespace tetskin
