// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A load curve (core LoadCurve.h) in a text file, for `tetskin simulate
// --load-curve`: one point per line, `TIME FACTOR` (seconds, times the
// loads), times strictly increasing, `#` starting a comment; a last line
// `repeat` repeats the curve after its last point (else its last factor
// holds).

#include <filesystem>

#include "tetskin/core/LoadCurve.h"

namespace tetskin {

// Throws Error naming the file and line for a line that is not two finite
// numbers or whose time does not follow the line before, for `repeat`
// after fewer than two points or followed by anything, and for a file
// without any point.
LoadCurve readLoadCurve(const std::filesystem::path& path);

}  // namespace tetskin
