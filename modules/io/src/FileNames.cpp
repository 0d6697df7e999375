// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/FileNames.h"

#include <cctype>

namespace tetskin {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace tetskin
