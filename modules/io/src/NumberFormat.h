// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <ostream>

namespace tetskin::detail {

// Writes the shortest text that reads back to exactly `value`.
void writeDouble(std::ostream& out, double value);

}  // namespace tetskin::detail
