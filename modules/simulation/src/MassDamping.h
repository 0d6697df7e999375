// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The mass share of Rayleigh damping as a force model: f = -alpha M v,
// D = alpha M (h alpha M on the system's diagonal; a coarse operator's mass
// scaled alike). The stiffness share, beta K, is ElasticForce's.

#include "ForceModel.h"

namespace tetskin {

class MassDamping : public ForceModel {
 public:
  // `mass` (lumped, per dof) outlives the model; `alpha` in 1/s.
  MassDamping(const Eigen::VectorXd& mass, double alpha);

  int addForce(const StepState& at, StepSystem& system) override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  void addCoarseTerms(double h, CoarseDiscretization& coarse) const override;

 private:
  const Eigen::VectorXd& mass_;
  double alpha_;
};

}  // namespace tetskin
