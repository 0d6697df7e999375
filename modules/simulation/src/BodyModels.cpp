// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BodyModels.h"

#include <algorithm>

#include "ElasticForce.h"
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
  // The floor is the last obstacle: the scene's keep their numbers.
  std::vector<Obstacle> obstacles = options.obstacles;
  if (const auto floor = options.floor())
    obstacles.push_back(floorObstacle(*floor, options.friction, options.floorStiffness));
  if (!obstacles.empty()) {
    // Contacts are looked for within a twentieth of the body's size: far
    // deeper than the automatic stiffness lets a node sink.
    Points3 rest = Eigen::Map<const Points3>(fem.restPositions().data(), fem.nodeCount(), 3);
    // (The automatic stiffness costs an element pass: only when one asks.)
    const bool automatic = std::any_of(obstacles.begin(), obstacles.end(),
                                       [](const Obstacle& o) { return o.stiffness == 0; });
    auto contact = std::make_unique<ObstacleContact>(
        std::move(obstacles), fem.lumpedMass(),
        automatic ? ObstacleContact::automaticStiffness(fem) : 0.0,
        0.05 * boundingBox(rest).diagonal());
    body.obstacles = contact.get();
    body.models.push_back(std::move(contact));
  }
  return body;
}

}  // namespace tetskin
