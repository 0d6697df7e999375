// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/RenderPath.h"

#include "tetskin/core/Error.h"

namespace tetskin {

RenderPath parseRenderPath(std::string_view name) {
  if (name == "cpu") return RenderPath::Cpu;
  if (name == "gpu-1pass") return RenderPath::Gpu1Pass;
  if (name == "gpu-2pass") return RenderPath::Gpu2Pass;
  if (name == "fur-cpu" || name == "fur-gpu")
    throw Error("render path '" + std::string(name) + "' is not available in this build yet");
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
  }
  return "?";
}

}  // namespace tetskin
