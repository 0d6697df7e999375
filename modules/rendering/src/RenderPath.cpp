// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/RenderPath.h"

#include "tetskin/core/Error.h"

namespace tetskin {

RenderPath parseRenderPath(std::string_view name) {
  if (name == "cpu") return RenderPath::Cpu;
  if (name == "gpu-1pass") return RenderPath::Gpu1Pass;
  if (name == "gpu-2pass" || name == "fur-cpu" || name == "fur-gpu")
    throw Error("render path '" + std::string(name) + "' is not available in this build yet");
  throw Error("unknown render path '" + std::string(name) +
              "' (known: cpu, gpu-1pass, gpu-2pass, fur-cpu, fur-gpu)");
}

const char* toString(RenderPath path) {
  return path == RenderPath::Cpu ? "cpu" : "gpu-1pass";
}

}  // namespace tetskin
