// SPDX-License-Identifier: AGPL-3.0-or-later
#include "NumberFormat.h"

#include <charconv>

namespace tetskin::detail {

void writeDouble(std::ostream& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.write(buffer, result.ptr - buffer);
}

}  // namespace tetskin::detail
