// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ObstacleContact.h"

#include <algorithm>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

ObstacleContact::ObstacleContact(std::vector<Obstacle> obstacles, const Eigen::VectorXd& mass,
                                 double automaticStiffness, double searchRadius)
    : obstacles_(std::move(obstacles)), mass_(mass), radius_(searchRadius) {
  for (const Obstacle& o : obstacles_) {
    if (const auto problem = obstacleProblem(o)) throw Error(*problem);
    stiffness_.push_back(o.stiffness > 0 ? o.stiffness : automaticStiffness);
  }
}

int ObstacleContact::addForce(const StepState& at, StepSystem& system) {
  h_ = at.h;
  t_ = at.t;
  contacts_.clear();
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const Obstacle& obstacle = obstacles_[o];
    const ObstaclePose now = obstacle.poseAt(at.t), next = obstacle.poseAt(at.t + at.h);
    for (Index node = 0; node < at.x.size() / 3; ++node) {
      const Eigen::Vector3d p = at.x.segment<3>(3 * node);
      const auto hit = closestPointOf(obstacle, at.t, p, radius_);
      if (!hit || hit->distance > 0) continue;  // touching counts, as on the floor
      const Eigen::Vector3d surfaceVelocity =
          (next.toWorld(now.toLocal(hit->point)) - hit->point) / at.h;
      contacts_.push_back(
          {node, static_cast<int>(o), -hit->distance, hit->normal, surfaceVelocity, p});
    }
  }
  const double h = at.h;
  for (const Contact& c : contacts_) {
    const double k = stiffness_[static_cast<std::size_t>(c.obstacle)];
    const Eigen::Vector3d v = at.v.segment<3>(3 * c.node);
    system.force.segment<3>(3 * c.node) +=
        k * (c.depth + h * c.normal.dot(c.velocity) - h * c.normal.dot(v)) * c.normal;
    for (int a = 0; a < 3; ++a)
      system.addSpring(3 * c.node + a, h * h * k * c.normal[a] * c.normal[a]);
  }
  return static_cast<int>(contacts_.size());
}

void ObstacleContact::addMatrix(const StepState& at, StepSystem& system) {
  // The off-diagonal entries of h^2 k n n^T (its diagonal went with the
  // springs): inside the node's own 3x3 block, which the pattern holds.
  const double h2 = at.h * at.h;
  for (const Contact& c : contacts_) {
    const double k = stiffness_[static_cast<std::size_t>(c.obstacle)];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (a != b)
          system.A->coeffRef(3 * c.node + a, 3 * c.node + b) += h2 * k * c.normal[a] * c.normal[b];
  }
}

void ObstacleContact::project(Eigen::VectorXd& x, Eigen::VectorXd& v) const {
  for (const Contact& c : contacts_) {
    const Obstacle& obstacle = obstacles_[static_cast<std::size_t>(c.obstacle)];
    const double k = stiffness_[static_cast<std::size_t>(c.obstacle)];
    const Eigen::Vector3d moved = x.segment<3>(3 * c.node) - c.start;
    // The spring's force at the step's end, as the step linearized it.
    const double normalForce =
        k * std::max(0.0, c.depth + h_ * c.normal.dot(c.velocity) - c.normal.dot(moved));
    const double allowance = h_ * normalForce / mass_[3 * c.node];
    Eigen::Vector3d relative = v.segment<3>(3 * c.node) - c.velocity;
    const Eigen::Vector3d tangential = relative - c.normal.dot(relative) * c.normal;
    const double speed = tangential.norm();
    if (speed == 0) continue;
    const Eigen::Vector3d change =
        speed <= obstacle.staticFriction * allowance
            ? Eigen::Vector3d(-tangential)
            : Eigen::Vector3d(-std::min(speed, obstacle.kineticFriction * allowance) / speed *
                              tangential);
    v.segment<3>(3 * c.node) += change;
    x.segment<3>(3 * c.node) += h_ * change;
  }
}

void ObstacleContact::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd&,
                                 Eigen::VectorXd& force) const {
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    for (Index node = 0; node < x.size() / 3; ++node) {
      const auto hit = closestPointOf(obstacles_[o], t_, x.segment<3>(3 * node), radius_);
      if (hit && hit->distance < 0)
        force.segment<3>(3 * node) -= stiffness_[o] * hit->distance * hit->normal;
    }
}

}  // namespace tetskin
