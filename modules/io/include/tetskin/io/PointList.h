// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Points named in a text file (`tetskin probe --points`): one point per
// line, `X Y Z`, `#` starting a comment.

#include <filesystem>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

struct PointList {
  Points3 points;           // #P x 3, in the file's order
  std::vector<long> lines;  // the line of each
};

// Throws Error naming the file and line for a line that is not three finite
// numbers, and for a file without any point.
PointList readPointList(const std::filesystem::path& path);

}  // namespace tetskin
