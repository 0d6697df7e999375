// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/UpAxis.h"

namespace tetskin {

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
