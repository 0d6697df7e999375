// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MassDamping.h"

namespace tetskin {

MassDamping::MassDamping(const Eigen::VectorXd& mass, double alpha) : mass_(mass), alpha_(alpha) {}

int MassDamping::addForce(const StepState& at, StepSystem& system) {
  system.diagonal += (at.h * alpha_) * mass_;
  addForceAt(at.x, at.v, system.force);
  return 0;
}

void MassDamping::addForceAt(const Eigen::VectorXd&, const Eigen::VectorXd& v,
                             Eigen::VectorXd& force) const {
  force -= alpha_ * mass_.cwiseProduct(v);
}

void MassDamping::addCoarseTerms(double h, CoarseDiscretization& coarse) const {
  coarse.massScale += h * alpha_;
}

}  // namespace tetskin
