// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/RenderPath.h"

#include "tetskin/core/Error.h"

namespace tetskin {

bool hasFur(RenderPath path) {
  return path == RenderPath::FurCpu || path == RenderPath::FurGpu;
}

RenderPath skinPath(RenderPath path) {
  if (path == RenderPath::FurCpu) return RenderPath::Cpu;
  if (path == RenderPath::FurGpu) return RenderPath::Gpu2Pass;
  return path;
}

}  // namespace tetskin
