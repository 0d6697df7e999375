// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A floor: the plane of points whose `up` coordinate is `height`. The
// simulation's contact plane (SimulationOptions::floorHeight along its up
// axis), recorded with a run's frames and drawn under the body.

#include "tetskin/core/UpAxis.h"

namespace tetskin {

struct FloorPlane {
  UpAxis up = UpAxis::Y;
  double height = 0;
  bool operator==(const FloorPlane&) const = default;
};

}  // namespace tetskin
