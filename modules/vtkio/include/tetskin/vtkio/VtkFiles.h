// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Atomic VTK XML writers (.vtp, .vtu) and checked readers, for exports that
// ParaView opens.

#include <vtkSmartPointer.h>

#include <filesystem>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace tetskin {

void writeVtp(const std::filesystem::path& path, vtkPolyData* data);
void writeVtu(const std::filesystem::path& path, vtkUnstructuredGrid* data);
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path);
vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& path);

}  // namespace tetskin
