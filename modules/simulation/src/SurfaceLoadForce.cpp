// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SurfaceLoadForce.h"

namespace tetskin {

SurfaceLoadForce::SurfaceLoadForce(std::vector<SurfaceLoad> loads, const Eigen::VectorXd& rest)
    : loads_(std::move(loads)), rest_(rest) {}

int SurfaceLoadForce::addForce(const StepState& at, StepSystem& system) {
  addForceAt(at.x, at.v, system.force);
  return 0;
}

void SurfaceLoadForce::addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd&,
                                  Eigen::VectorXd& force) const {
  const double factor = factor_.load();
  if (factor == 0) return;
  for (const SurfaceLoad& load : loads_) addSurfaceLoadForces(load, rest_, x, factor, force);
}

void SurfaceLoadForce::addEnergy(const Eigen::VectorXd& x, Energies& energies) const {
  const double factor = factor_.load();
  for (const SurfaceLoad& load : loads_) energies.load += surfaceLoadEnergy(load, rest_, x, factor);
}

}  // namespace tetskin
