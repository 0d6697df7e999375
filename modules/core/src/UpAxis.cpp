// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/UpAxis.h"

#include <cctype>
#include <string>

namespace tetskin {

const char* toString(UpAxis up) {
  switch (up) {
    case UpAxis::X:
      return "x";
    case UpAxis::Y:
      return "y";
    case UpAxis::Z:
      return "z";
  }
  return "y";
}

std::optional<UpAxis> parseUpAxis(std::string_view name) {
  if (name.size() != 1) return std::nullopt;
  switch (std::tolower(static_cast<unsigned char>(name[0]))) {
    case 'x':
      return UpAxis::X;
    case 'y':
      return UpAxis::Y;
    case 'z':
      return UpAxis::Z;
    default:
      return std::nullopt;
  }
}

std::vector<std::string> upAxisNames() {
  return {toString(UpAxis::X), toString(UpAxis::Y), toString(UpAxis::Z)};
}

Eigen::Vector3d upVector(UpAxis up) {
  return Eigen::Vector3d::Unit(axisIndex(up));
}

Eigen::Matrix3d fromYUp(UpAxis up) {
  Eigen::Matrix3d r;
  switch (up) {
    case UpAxis::X:  // y -> x, x -> -y, z stays (a quarter turn about z)
      r << 0, 1, 0, -1, 0, 0, 0, 0, 1;
      break;
    case UpAxis::Y:
      r.setIdentity();
      break;
    case UpAxis::Z:  // y -> z, z -> -y, x stays (a quarter turn about x)
      r << 1, 0, 0, 0, 0, -1, 0, 1, 0;
      break;
  }
  return r;
}

}  // namespace tetskin
