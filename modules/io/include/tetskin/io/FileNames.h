// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <filesystem>
#include <string>

namespace tetskin {

// The file's extension with its dot, in lower case (".OBJ" -> ".obj"), so
// formats are recognised whatever the case.
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace tetskin
