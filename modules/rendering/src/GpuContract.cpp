// SPDX-License-Identifier: AGPL-3.0-or-later
#include "GpuContract.h"

namespace tetskin::gpu {

std::string withSlots(std::string_view source) {
  std::string defines;
  for (const SlotName& s : kSlots)
    defines += "#define " + std::string(s.define) + " " + std::to_string(index(s.slot)) + "\n";
  const std::size_t firstLineEnd = source.find('\n');
  if (firstLineEnd == std::string_view::npos) return std::string(source) + "\n" + defines;
  return std::string(source.substr(0, firstLineEnd + 1)) + defines +
         std::string(source.substr(firstLineEnd + 1));
}

}  // namespace tetskin::gpu
