// SPDX-License-Identifier: AGPL-3.0-or-later
#include "OptionChecks.h"

#include <charconv>
#include <cmath>
#include <string>

namespace tetskin::cli {

CLI::Validator wholeNumber(long long min, long long max) {
  const std::string range = max == std::numeric_limits<int>::max()
                                ? ">= " + std::to_string(min)
                                : "in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end)
          return "'" + text + "' is not a whole number";
        if (value < min || value > max) return text + " is not " + range;
        return {};
      },
      // Shown in --help after the type, as CLI11's own checks are.
      max != std::numeric_limits<int>::max()
          ? "[" + std::to_string(min) + ", " + std::to_string(max) + "]"
      : min == 0 ? "NONNEGATIVE"
      : min == 1 ? "POSITIVE"
                 : ">= " + std::to_string(min));
}

CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        if (!(value > 0)) return text + " is not > 0";
        return {};
      },
      "POSITIVE");
}

}  // namespace tetskin::cli
