// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What holds a simulated control mesh, the same all through a run: the
// floor, if any, and the nodes whose motion is prescribed (held still, or
// driven as the twist's top). A Simulation says its own
// (Simulation::conditions()); a recorded run keeps them in every frame, so
// that it is drawn and inspected with them.

#include <optional>
#include <vector>

#include "tetskin/core/FloorPlane.h"

namespace tetskin {

struct RunConditions {
  std::optional<FloorPlane> floor;
  std::vector<int> prescribedNodes;  // the level's node ids
};

}  // namespace tetskin
