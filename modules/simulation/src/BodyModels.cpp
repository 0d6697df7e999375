// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BodyModels.h"

#include <optional>

#include "ElasticForce.h"
#include "FloorContact.h"
#include "Gravity.h"
#include "MassDamping.h"
#include "ObstacleContact.h"
#include "tetskin/core/Geometry.h"

namespace tetskin {

BodyModels bodyModels(CorotatedFem& fem, const SimulationOptions& options) {
  BodyModels body;
  const ElasticMaterial& m = options.material;
  body.models.push_back(std::make_unique<ElasticForce>(fem, m.stiffnessDamping, options.tangent));
  body.models.push_back(
      std::make_unique<Gravity>(fem.lumpedMass(), fem.restPositions(), options.gravity));
  body.models.push_back(std::make_unique<MassDamping>(fem.lumpedMass(), m.massDamping));
  auto constraints = std::make_unique<NodeConstraints>(fem.pattern());
  body.constraints = constraints.get();
  body.models.push_back(std::move(constraints));
  // (An element pass: made once, for the floor and the obstacles both.)
  std::optional<double> automatic;
  const auto automaticStiffness = [&] {
    if (!automatic) automatic = FloorContact::automaticStiffness(fem);
    return *automatic;
  };
  if (const auto floor = options.floor())
    body.models.push_back(std::make_unique<FloorContact>(
        *floor, options.floorStiffness > 0 ? options.floorStiffness : automaticStiffness(),
        options.friction));
  if (!options.obstacles.empty()) {
    // Contacts are looked for within a twentieth of the body's size: far
    // deeper than the automatic stiffness lets a node sink.
    Points3 rest = Eigen::Map<const Points3>(fem.restPositions().data(), fem.nodeCount(), 3);
    auto obstacles =
        std::make_unique<ObstacleContact>(options.obstacles, fem.lumpedMass(), automaticStiffness(),
                                          0.05 * boundingBox(rest).diagonal());
    body.obstacles = obstacles.get();
    body.models.push_back(std::move(obstacles));
  }
  return body;
}

}  // namespace tetskin
