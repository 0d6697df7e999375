// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The surface loads (SurfaceLoad.h) as a force model: their consistent
// nodal forces at the step's start, times the load curve's factor, with no
// stiffness of their own (a pressure's turn with the surface lags a step,
// as the loads on nodes do); their potential energy into
// Energies::load.

#include <atomic>
#include <vector>

#include "ForceModel.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin {

class SurfaceLoadForce : public ForceModel {
 public:
  // `loads`' faces in the body's internal node numbers; `rest` (3n)
  // outlives the model.
  SurfaceLoadForce(std::vector<SurfaceLoad> loads, const Eigen::VectorXd& rest);

  // The load curve's factor from the next step on (safe while another
  // thread reads the forces).
  void setFactor(double factor) { factor_.store(factor); }
  double factor() const { return factor_.load(); }

  int addForce(const StepState& at, StepSystem& system) override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  void addEnergy(const Eigen::VectorXd& x, Energies& energies) const override;

 private:
  std::vector<SurfaceLoad> loads_;
  const Eigen::VectorXd& rest_;
  std::atomic<double> factor_{1.0};
};

}  // namespace tetskin
