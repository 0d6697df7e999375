// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/RenderPath.h"

#include "tetskin/core/Error.h"

namespace tetskin {

RenderPath parseRenderPath(std::string_view name) {
  if (name == "cpu") return RenderPath::Cpu;
  if (name == "gpu-1pass") return RenderPath::Gpu1Pass;
  if (name == "gpu-2pass") return RenderPath::Gpu2Pass;
  if (name == "fur-cpu") return RenderPath::FurCpu;
  if (name == "fur-gpu") return RenderPath::FurGpu;
  throw Error("unknown render path '" + std::string(name) +
              "' (known: cpu, gpu-1pass, gpu-2pass, fur-cpu, fur-gpu)");
}

const char* toString(RenderPath path) {
  switch (path) {
    case RenderPath::Cpu:
      return "cpu";
    case RenderPath::Gpu1Pass:
      return "gpu-1pass";
    case RenderPath::Gpu2Pass:
      return "gpu-2pass";
    case RenderPath::FurCpu:
      return "fur-cpu";
    case RenderPath::FurGpu:
      return "fur-gpu";
  }
  return "?";
}

bool hasFur(RenderPath path) {
  return path == RenderPath::FurCpu || path == RenderPath::FurGpu;
}

RenderPath skinPath(RenderPath path) {
  if (path == RenderPath::FurCpu) return RenderPath::Cpu;
  if (path == RenderPath::FurGpu) return RenderPath::Gpu2Pass;
  return path;
}

}  // namespace tetskin
