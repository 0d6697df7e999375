// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A list of node numbers in a text file, e.g. the nodes `tetskin simulate
// --fixed-nodes` holds still: numbers from 0 (the point ids ParaView shows
// for a level's .vtu), separated by spaces or line breaks, `#` starting a
// comment. A number given twice counts once.

#include <filesystem>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

// Throws Error naming the file and line for a token that is not a whole
// number or names no node of a mesh with `nodeCount` nodes, and for a file
// without any number. Returns the numbers sorted, each once.
std::vector<int> readNodeList(const std::filesystem::path& path, Index nodeCount);

}  // namespace tetskin
