// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Obstacle.h"

#include <algorithm>
#include <cmath>

#include "ContactCoefficients.h"
#include "tetskin/core/Error.h"

namespace tetskin {

ObstaclePose Obstacle::poseAt(double t) const {
  if (motion.empty()) return placement;
  ObstaclePose pose = placement;
  const auto after = std::upper_bound(motion.begin(), motion.end(), t,
                                      [](double time, const PoseKey& k) { return time < k.time; });
  if (after == motion.begin() || after == motion.end()) {
    const PoseKey& key = after == motion.begin() ? motion.front() : motion.back();
    pose.translation = key.translation;
    pose.rotation = key.rotation;
    return pose;
  }
  const PoseKey& a = *(after - 1);
  const PoseKey& b = *after;
  const double s = (t - a.time) / (b.time - a.time);
  pose.translation = (1 - s) * a.translation + s * b.translation;
  pose.rotation = a.rotation.slerp(s, b.rotation);
  return pose;
}

Obstacle floorObstacle(const FloorPlane& floor, double friction, double stiffness) {
  Obstacle o;
  o.name = "the floor";
  o.floor = floor;
  o.staticFriction = o.kineticFriction = friction;
  o.stiffness = stiffness;
  return o;
}

Obstacle placedAt(Obstacle obstacle, const ObstaclePose& placement) {
  obstacle.placement = placement;
  if (const auto problem = obstacleProblem(obstacle)) throw Error(*problem);
  return obstacle;
}

std::optional<std::string> contactCoefficientProblem(double staticFriction, double kineticFriction,
                                                     double stiffness) {
  if (!(std::isfinite(staticFriction) && std::isfinite(kineticFriction) && kineticFriction >= 0 &&
        staticFriction >= kineticFriction))
    return "friction must satisfy 0 <= kinetic <= static, got static " +
           formatNumber(staticFriction) + " and kinetic " + formatNumber(kineticFriction);
  if (!(std::isfinite(stiffness) && stiffness >= 0))
    return "the stiffness must be finite and >= 0 (0: automatic), got " + formatNumber(stiffness);
  return std::nullopt;
}

std::optional<std::string> obstacleProblem(const Obstacle& o) {
  const std::string name = o.name.empty() ? std::string("an obstacle") : o.name;
  if (!o.shape && !o.floor) return name + ": no surface";
  if (o.floor && !std::isfinite(o.floor->height))
    return name + ": the height must be finite, got " + formatNumber(o.floor->height);
  if (const auto problem =
          contactCoefficientProblem(o.staticFriction, o.kineticFriction, o.stiffness))
    return name + ": " + *problem;
  const auto poseProblem = [&](const Eigen::Vector3d& translation,
                               const Eigen::Quaterniond& rotation) -> std::optional<std::string> {
    if (!translation.allFinite()) return name + ": the translation must be finite";
    if (!rotation.coeffs().allFinite() || std::abs(rotation.norm() - 1) > 1e-9)
      return name + ": the rotation must be a unit quaternion";
    return std::nullopt;
  };
  if (!(std::isfinite(o.placement.scale) && o.placement.scale > 0))
    return name + ": the scale must be finite and positive, got " + formatNumber(o.placement.scale);
  if (auto problem = poseProblem(o.placement.translation, o.placement.rotation)) return problem;
  for (std::size_t k = 0; k < o.motion.size(); ++k) {
    const PoseKey& key = o.motion[k];
    if (!std::isfinite(key.time) || (k > 0 && key.time <= o.motion[k - 1].time))
      return name + ": keyframe " + std::to_string(k) +
             "'s time must be finite and later than the one before";
    if (auto problem = poseProblem(key.translation, key.rotation))
      return *problem + " (keyframe " + std::to_string(k) + ")";
  }
  return std::nullopt;
}

std::optional<SurfacePoint> closestPointOf(const Obstacle& obstacle, double t,
                                           const Eigen::Vector3d& p, double radius) {
  if (obstacle.floor) {
    // Exact and at any depth: a half-space has no far side to mistake.
    const int up = axisIndex(obstacle.floor->up);
    SurfacePoint hit;
    hit.distance = p[up] - obstacle.floor->height;
    if (hit.distance > radius) return std::nullopt;
    hit.point = p;
    hit.point[up] = obstacle.floor->height;
    hit.normal = Eigen::Vector3d::Unit(up);
    return hit;
  }
  const ObstaclePose pose = obstacle.poseAt(t);
  std::optional<SurfacePoint> hit = obstacle.shape->closest(pose.toLocal(p), radius / pose.scale);
  if (!hit) return hit;
  hit->distance *= pose.scale;
  hit->point = pose.toWorld(hit->point);
  hit->normal = pose.rotation * hit->normal;
  return hit;
}

}  // namespace tetskin
