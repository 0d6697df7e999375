// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The implicit (backward) Euler step of the corotated body, linearized
// once per step: (M + h C + h^2 K_T) dv = h (f - C v - h K_T v + f_ext + M g)
// with Rayleigh damping C = alpha M + beta K and the tangent K_T = K +
// K_rot (K_rot only with the full tangent: CorotatedFem::SystemTerms), then
// v += dv, x += h v. Another integrator replaces this class: the stepper
// asks it for the system of a step, the discretization of its coarse
// operators, and the step's outcome.

#include "tetskin/simulation/Simulation.h"

namespace tetskin {

// How a coarser level's own FEM becomes a coarse operator of the step's
// system (rediscretized multigrid): terms.stiffnessScale K + terms.
// rotationScale K_rot + massScale M (+ the contact's diagonal).
struct CoarseDiscretization {
  double massScale = 1;
  CorotatedFem::SystemTerms terms;
};

class ImplicitEuler {
 public:
  // For `fem` (whose lumped mass it damps), steps of options.timeStep.
  ImplicitEuler(const SimulationOptions& options, const CorotatedFem& fem);

  double timeStep() const { return h_; }

  // A (values, in `fem`'s pattern) and b of the step from (x, v) under
  // `external` forces; `contactDiagonal` and `contactForce` (null: none)
  // add a contact's linearized springs. Returns the seconds of the element
  // pass.
  double assemble(CorotatedFem& fem, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  const Eigen::VectorXd& external, const Eigen::VectorXd* contactDiagonal,
                  const Eigen::VectorXd* contactForce, SparseMatrix& A, Eigen::VectorXd& b);

  CoarseDiscretization coarseDiscretization() const;

  // The step's outcome: v + dv, x + h (v + dv).
  void advance(const Eigen::VectorXd& x, const Eigen::VectorXd& v, const Eigen::VectorXd& dv,
               Eigen::VectorXd& newX, Eigen::VectorXd& newV) const;

 private:
  double h_;
  ElasticMaterial material_;
  Eigen::Vector3d gravity_;
  Tangent tangent_;
  const Eigen::VectorXd& mass_;  // lumped, per dof
  Eigen::VectorXd dampedMass_;   // (1 + h alpha) M
  Eigen::VectorXd diagonal_;     // dampedMass_ + the contact's diagonal
  Eigen::VectorXd force_;        // the element pass's
};

}  // namespace tetskin
