// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

// How the bound surface is deformed and drawn (the report's Table 6.1 columns).
enum class RenderPath {
  Cpu,       // threaded CPU deformer, points and normals updated in the vtkPolyData
  Gpu1Pass,  // vertex shader deformation from a per-frame control-state texture buffer
  Gpu2Pass,  // compute pass into GPU buffers (positions, smooth normals), then the draw
  FurCpu,    // the cpu skin plus shells (and fins) the CPU places every frame
  FurGpu,    // the gpu-2pass skin plus shells drawn instanced from its GPU buffers
};

template <>
struct EnumSchema<RenderPath> {
  static constexpr const char* what = "render path";
  static constexpr EnumValue<RenderPath> values[] = {
      {RenderPath::Cpu, "cpu", "threaded CPU deformer"},
      {RenderPath::Gpu1Pass, "gpu-1pass", "vertex shader deformation"},
      {RenderPath::Gpu2Pass, "gpu-2pass", "compute pass into GPU buffers, then the draw"},
      {RenderPath::FurCpu, "fur-cpu", "the cpu skin with shells placed on the CPU"},
      {RenderPath::FurGpu, "fur-gpu", "the gpu-2pass skin with instanced shells"}};
};
inline constexpr EnumOption<RenderPath> kRenderPathOption{"path", "--path", "the render path"};
// The path `render` and the GUI's View dock start on.
inline constexpr RenderPath kDefaultRenderPath = RenderPath::Cpu;
bool hasFur(RenderPath path);
// How the skin under the fur is drawn (the path itself for the plain paths).
RenderPath skinPath(RenderPath path);

}  // namespace tetskin
