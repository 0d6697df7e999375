// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The corotated FEM as a force model, with its share of Rayleigh damping
// (beta K: computed in the same element pass, which is why it is not a
// model of its own) and, with the full tangent, the rotation term K_rot:
// A = (h beta + h^2) K + h^2 K_rot + the diagonal the other models built,
// f = f_el - (beta + h) K v - h K_rot v (the -h K v of ForceModel.h
// included). It writes A, so it is the first model of a list.

#include "ForceModel.h"

namespace tetskin {

class ElasticForce : public ForceModel {
 public:
  // `fem` outlives the model; `stiffnessDamping` is beta (s).
  ElasticForce(CorotatedFem& fem, double stiffnessDamping, Tangent tangent);

  void addMatrix(const StepState& at, StepSystem& system) override;
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  void addEnergy(const Eigen::VectorXd& x, Energies& energies) const override;
  void addCoarseTerms(double h, CoarseDiscretization& coarse) const override;

 private:
  CorotatedFem& fem_;
  double beta_;
  Tangent tangent_;
  Eigen::VectorXd force_;  // the element pass's
};

// The largest diagonal entry of `fem`'s stiffness at its rest positions (an
// element pass): the scale of the body's stiffness that the contacts'
// automatic stiffness and the static solve's regularization are set by.
double stiffestRestDiagonal(CorotatedFem& fem);

}  // namespace tetskin
