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
};

// Throws Error for an unknown path, and for the report's paths this build does
// not have yet (fur-cpu, fur-gpu), saying so.
RenderPath parseRenderPath(std::string_view name);
const char* toString(RenderPath path);

}  // namespace tetskin
