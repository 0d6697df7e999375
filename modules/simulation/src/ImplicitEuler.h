// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The implicit (backward) Euler step, linearized once per step:
// (M + h D + h^2 K) dv = h (f - h K v + f_ext), summed over the body's force
// models (ForceModel.h: elasticity with its damping, gravity, mass damping,
// contacts), whose constraints then decide their rows; then v += dv,
// x += h v, and the models' projections. Another integrator replaces this
// class: the stepper asks it for the system of a step, the discretization
// of its coarse operators, and the step's outcome.

#include <memory>
#include <vector>

#include "ForceModel.h"

namespace tetskin {

// A body's force models, in the order they act: the elastic model first
// (it writes the matrix), the constraints before the contacts (whose
// projection has the last word on a node).
using ForceModels = std::vector<std::unique_ptr<ForceModel>>;

class ImplicitEuler {
 public:
  // Steps of `timeStep` seconds for a body of lumped `mass` (per dof; it
  // outlives the integrator). `still`: the steps of a static solve, in a
  // world that stands still (StepState::still).
  ImplicitEuler(double timeStep, const Eigen::VectorXd& mass, bool still = false);

  double timeStep() const { return h_; }

  // A (values, in the elastic model's pattern) and b of the step from
  // (x, v) at time t under `external` loads (3n, N), with the constraints'
  // rows decided. Returns the contacts the models found.
  int assemble(const ForceModels& models, double t, const Eigen::VectorXd& x,
               const Eigen::VectorXd& v, const Eigen::VectorXd& external, SparseMatrix& A,
               Eigen::VectorXd& b);
  // The springs' share of the last assembled diagonal, per dof (null: no
  // spring acted), for rediscretized coarse operators.
  const Eigen::VectorXd* springs() const { return system_.hasSprings ? &system_.springs : nullptr; }
  // The last assembled system's springs outside the pattern (null: none),
  // a part of the system the solve must include.
  // The last assembled system (a force model takes its share out of it).
  StepSystem& stepSystem() { return system_; }
  const CouplingSprings* coupling() const {
    return system_.coupling.empty() ? nullptr : &system_.coupling;
  }

  CoarseDiscretization coarseDiscretization(const ForceModels& models) const;

  // The step's outcome: v + dv, x + h (v + dv), then the models'
  // projections in their order.
  void advance(const ForceModels& models, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
               const Eigen::VectorXd& dv, Eigen::VectorXd& newX, Eigen::VectorXd& newV) const;

 private:
  double h_;
  const Eigen::VectorXd& mass_;
  bool still_;
  StepSystem system_;
};

}  // namespace tetskin
