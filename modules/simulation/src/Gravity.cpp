// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Gravity.h"

namespace tetskin {

Gravity::Gravity(const Eigen::VectorXd& mass, const Eigen::VectorXd& rest, const Eigen::Vector3d& g)
    : mass_(mass), rest_(rest), g_(g) {}

int Gravity::addForce(const StepState& at, StepSystem& system) {
  addForceAt(at.x, at.v, system.force);
  return 0;
}

void Gravity::addForceAt(const Eigen::VectorXd&, const Eigen::VectorXd&,
                         Eigen::VectorXd& force) const {
  for (Index node = 0; node < force.size() / 3; ++node)
    force.segment<3>(3 * node) += mass_.segment<3>(3 * node).cwiseProduct(g_);
}

void Gravity::addEnergy(const Eigen::VectorXd& x, Energies& energies) const {
  for (Index node = 0; node < x.size() / 3; ++node)
    energies.gravitational -=
        mass_[3 * node] * g_.dot(x.segment<3>(3 * node) - rest_.segment<3>(3 * node));
}

}  // namespace tetskin
