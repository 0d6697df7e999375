// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Gravity as a force model: f = M g on the lumped masses, no stiffness;
// its potential energy -sum m g . (x - X) from the rest positions X.

#include "ForceModel.h"

namespace tetskin {

class Gravity : public ForceModel {
 public:
  // `mass` (lumped, per dof) and `rest` (3n) outlive the model; g in m/s^2.
  Gravity(const Eigen::VectorXd& mass, const Eigen::VectorXd& rest, const Eigen::Vector3d& g);

  int addForce(const StepState& at, StepSystem& system) override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  void addEnergy(const Eigen::VectorXd& x, Energies& energies) const override;

 private:
  const Eigen::VectorXd& mass_;
  const Eigen::VectorXd& rest_;
  Eigen::Vector3d g_;
};

}  // namespace tetskin
