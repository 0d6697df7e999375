// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The force models of one body (ForceModel.h), built from its options: the
// one place that lists them. A new contact model is a line here.

#include "ImplicitEuler.h"
#include "NodeConstraints.h"

namespace tetskin {

class ObstacleContact;

struct BodyModels {
  ForceModels models;
  NodeConstraints* constraints = nullptr;  // one of `models`: fixed and driven nodes
  ObstacleContact* obstacles = nullptr;    // one of `models` when there are obstacles or a floor
};

// Elasticity (with stiffness damping), gravity, mass damping, the fixed and
// driven nodes (none yet: set them through `constraints`) and contact with
// the obstacles and the floor if the options have any, in that order, for
// the body `fem` (which outlives them).
BodyModels bodyModels(CorotatedFem& fem, const SimulationOptions& options);

}  // namespace tetskin
