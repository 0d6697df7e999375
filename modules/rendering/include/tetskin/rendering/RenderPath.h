// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace tetskin {

// How the bound surface is deformed and drawn (the report's Table 6.1 columns).
enum class RenderPath {
  Cpu,       // threaded CPU deformer, points and normals updated in the vtkPolyData
  Gpu1Pass,  // vertex shader deformation from a per-frame control-state texture buffer
  Gpu2Pass,  // compute pass into GPU buffers (positions, smooth normals), then the draw
  FurCpu,    // the cpu skin plus shells (and fins) the CPU places every frame
  FurGpu,    // the gpu-2pass skin plus shells drawn instanced from its GPU buffers
};

// Throws Error for an unknown path.
RenderPath parseRenderPath(std::string_view name);
const char* toString(RenderPath path);
bool hasFur(RenderPath path);
// How the skin under the fur is drawn (the path itself for the plain paths).
RenderPath skinPath(RenderPath path);

}  // namespace tetskin
