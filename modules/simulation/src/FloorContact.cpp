// SPDX-License-Identifier: AGPL-3.0-or-later
#include "FloorContact.h"

#include <algorithm>

namespace tetskin {

FloorContact::FloorContact(const FloorPlane& floor, double stiffness, double friction)
    : floor_(floor), up_(axisIndex(floor.up)), stiffness_(stiffness), friction_(friction) {}

double FloorContact::automaticStiffness(CorotatedFem& fem) {
  Eigen::VectorXd force;
  SparseMatrix stiffness = fem.pattern();
  fem.update(fem.restPositions(), force, stiffness);
  return 100.0 * stiffness.diagonal().maxCoeff();
}

int FloorContact::addForce(const StepState& at, StepSystem& system) {
  const double h = at.h;
  int contacts = 0;
  for (Index node = 0; node < at.x.size() / 3; ++node) {
    const Index dof = 3 * node + up_;
    const double depth = floor_.height - at.x[dof];
    if (depth < 0) continue;  // touching counts: the penalty keeps it from sinking
    ++contacts;
    system.addSpring(dof, h * h * stiffness_);
    system.force[dof] += stiffness_ * depth - h * stiffness_ * at.v[dof];
  }
  return contacts;
}

void FloorContact::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd&,
                              Eigen::VectorXd& force) const {
  for (Index node = 0; node < x.size() / 3; ++node) {
    const Index dof = 3 * node + up_;
    force[dof] += stiffness_ * std::max(floor_.height - x[dof], 0.0);
  }
}

void FloorContact::project(Eigen::VectorXd& x, Eigen::VectorXd& v) const {
  for (Index node = 0; node < x.size() / 3; ++node) {
    if (x[3 * node + up_] >= floor_.height) continue;
    x[3 * node + up_] = floor_.height;
    v[3 * node + up_] = std::max(v[3 * node + up_], 0.0);
    v[3 * node + (up_ + 1) % 3] *= 1 - friction_;
    v[3 * node + (up_ + 2) % 3] *= 1 - friction_;
  }
}

}  // namespace tetskin
