// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Contact with a floor plane by penalty springs: a node on or below the
// plane gets a spring of stiffness k pulling it up, linearized into the
// implicit step (h^2 k on the system's diagonal, like the mass; its force
// with the spring's damping on the right-hand side); after the step a node
// still below is put on the plane, its velocity into the floor removed and
// its tangential velocity reduced by friction. A force model
// (ForceModel.h).

#include "ForceModel.h"
#include "tetskin/core/FloorPlane.h"

namespace tetskin {

class FloorContact : public ForceModel {
 public:
  // `stiffness` > 0; `friction` in [0, 1].
  FloorContact(const FloorPlane& floor, double stiffness, double friction);

  // About a hundred times the stiffest element diagonal of `fem` at its
  // rest positions: penetration stays small without ruining the
  // conditioning of the system.
  static double automaticStiffness(CorotatedFem& fem);

  double stiffness() const { return stiffness_; }

  // The springs of a step: h^2 k on the diagonal and k depth - h k v in
  // the force, per node on or below the plane; returns those nodes.
  int addForce(const StepState& at, StepSystem& system) override;
  // The step's outcome (x, v) with every node below the plane put on it.
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v) const override;
  // k depth per node below the plane.
  void addForceAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                  Eigen::VectorXd& force) const override;
  bool isContact() const override { return true; }

 private:
  FloorPlane floor_;
  int up_;  // the axis of the plane's normal
  double stiffness_, friction_;
};

}  // namespace tetskin
