// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/NumberText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tetskin/core/Error.h"

namespace tetskin {

std::string formatToScale(double value, double scale, int digits) {
  char text[48];
  if (!std::isfinite(value)) {
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }
  digits = std::clamp(digits, 1, 17);
  if (!(scale > 0) || !std::isfinite(scale)) scale = std::abs(value);
  if (scale == 0) return "0";
  // The resolution: the last meaningful digit's place at the scale.
  const int scaleExponent = static_cast<int>(std::floor(std::log10(scale)));
  const double resolution = std::pow(10.0, scaleExponent - digits + 1);
  const double rounded = std::round(value / resolution) * resolution;
  if (rounded == 0) return "0";
  // The digits of `rounded` down to the resolution.
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(rounded))));
  const int significant = std::clamp(exponent - scaleExponent + digits, 1, 17);
  std::snprintf(text, sizeof text, "%.*g", significant, rounded);
  return text;
}

std::string commaSeparatedToScale(const Eigen::Vector3d& v, int digits, double floor) {
  const double scale = std::max(v.cwiseAbs().maxCoeff(), floor);
  return formatToScale(v.x(), scale, digits) + "," + formatToScale(v.y(), scale, digits) + "," +
         formatToScale(v.z(), scale, digits);
}

std::string outOfRange(double min, double max, bool minExclusive, const std::string& found) {
  return "must lie in " + std::string(minExclusive ? "(" : "[") + formatNumber(min) + ", " +
         formatNumber(max) + "], found " + found;
}

}  // namespace tetskin
