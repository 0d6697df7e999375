// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// An obstacle: a closed surface the body cannot enter, placed by a rigid
// transform with a uniform scale, static or moved kinematically through
// keyframes, with Coulomb friction against the body. Its shape is shared
// (a scene may place one surface several times) and read-only. The floor
// is the simplest obstacle: the half-space below a plane, its distance
// exact and computed, not looked up (floorObstacle).

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/FloorPlane.h"
#include "tetskin/spatial/ClosedSurfaceDistance.h"

namespace tetskin {

// x -> translation + scale * rotation * x: where the obstacle's own
// coordinates lie in the world's.
struct ObstaclePose {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // unit
  double scale = 1;

  Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const {
    return translation + scale * (rotation * local);
  }
  Eigen::Vector3d toLocal(const Eigen::Vector3d& world) const {
    return rotation.conjugate() * (world - translation) / scale;
  }
  // toWorld as one affine map (for drawing and writing the posed surface).
  Eigen::Affine3d affine() const {
    Eigen::Affine3d map = Eigen::Affine3d::Identity();
    map.translate(translation).rotate(rotation).scale(scale);
    return map;
  }
};

// A keyframe of a kinematic obstacle: at `time` (s) its translation and
// rotation (the scale stays the placement's).
struct PoseKey {
  double time = 0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

struct Obstacle {
  std::string name;                                    // in messages: the file, or "obstacle 2"
  std::shared_ptr<const ClosedSurfaceDistance> shape;  // in its own coordinates
  // The floor, in place of a shape: the half-space below this plane, in
  // world coordinates (placement and motion do not apply).
  std::optional<FloorPlane> floor;
  ObstaclePose placement;  // a static obstacle's pose; a moving one's scale
  // Keyframes, times strictly increasing (empty: static). Between two the
  // translation is linear and the rotation spherical; before the first and
  // after the last the obstacle rests at that key's pose.
  std::vector<PoseKey> motion;
  double staticFriction = 0.5;   // mu_s >= mu_k
  double kineticFriction = 0.4;  // mu_k >= 0
  double stiffness = 0;          // penalty k (N/m); 0 = automatic (as the floor's)

  // Its pose at time t.
  ObstaclePose poseAt(double t) const;
};

// The floor as an obstacle: named "the floor", with `friction` as its
// static and kinetic coefficient and the penalty `stiffness` (0: automatic).
Obstacle floorObstacle(const FloorPlane& floor, double friction, double stiffness);

// What is wrong with `obstacle` (no shape, friction or stiffness out of
// range, a zero scale, keyframes out of order or not unit), named by its
// name; nullopt when nothing is.
std::optional<std::string> obstacleProblem(const Obstacle& obstacle);

// `obstacle` at `placement` (a static one's pose, a moving one's scale; its
// keyframes stay). Throws Error with obstacleProblem's message for a
// placement it refuses.
Obstacle placedAt(Obstacle obstacle, const ObstaclePose& placement);

// The closest point of `obstacle` at time t to the world point p, in world
// coordinates (distance, point and normal); nullopt when farther than
// `radius` (world units) from its surface (the floor: only above it).
std::optional<SurfacePoint> closestPointOf(const Obstacle& obstacle, double t,
                                           const Eigen::Vector3d& p, double radius);

}  // namespace tetskin
