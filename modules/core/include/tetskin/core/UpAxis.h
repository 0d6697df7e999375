// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Which coordinate axis points up in a dataset: y for the bundled bunny and
// most graphics models, z for most CAD, 3D-printing (STL) and GIS data. The
// scenarios' base, push, drop and twist, the floor, the default gravity and
// the camera presets follow it, so a z-up model stands on its feet.

#include <Eigen/Core>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

enum class UpAxis { X = 0, Y = 1, Z = 2 };

// "x", "y", "z" (any letter case), in coordinate order: the choices the
// command line and the GUI offer.
template <>
struct EnumSchema<UpAxis> {
  static constexpr const char* what = "up axis";
  static constexpr EnumValue<UpAxis> values[] = {
      {UpAxis::X, "x", ""}, {UpAxis::Y, "y", ""}, {UpAxis::Z, "z", ""}};
  static constexpr bool anyCase = true;
};
// The option (build's: the inputs' up, written to the config; a run's: the
// config's up replaced). Its default: the config's, else y.
inline constexpr EnumOption<UpAxis> kUpOption{"up", "--up", "the up axis",
                                              "the axis that points up: "};

// The coordinate index (0, 1, 2).
inline int axisIndex(UpAxis up) {
  return static_cast<int>(up);
}

// The unit vector along the axis.
Eigen::Vector3d upVector(UpAxis up);

// The rotation taking the y-up frame to this one (a proper rotation taking
// y to the up axis, so what is horizontal for y-up stays horizontal): how a
// direction given for y-up (a camera preset, a sideways push) reads for this
// axis. Identity for y.
Eigen::Matrix3d fromYUp(UpAxis up);

}  // namespace tetskin
