// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Contact with a floor plane by penalty springs: a node on or below the
// plane gets a spring of stiffness k pulling it up, linearized into the
// implicit step (h^2 k on the system's diagonal, like the mass; its force
// with the spring's damping on the right-hand side); after the step a node
// still below is put on the plane, its velocity into the floor removed and
// its tangential velocity reduced by friction. Another contact model
// replaces this class (the stepper reads diagonal() and force() and calls
// project()).

#include "tetskin/core/FloorPlane.h"
#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

class FloorContact {
 public:
  // `stiffness` > 0; `friction` in [0, 1].
  FloorContact(const FloorPlane& floor, double stiffness, double friction);

  // About a hundred times the stiffest element diagonal of `fem` at its
  // rest positions: penetration stays small without ruining the
  // conditioning of the system.
  static double automaticStiffness(CorotatedFem& fem);

  double stiffness() const { return stiffness_; }

  // The springs of a step of length h from positions x and velocities v
  // (3n each): diagonal() and force() for it; returns the nodes in contact.
  int linearize(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double h);
  const Eigen::VectorXd& diagonal() const { return diagonal_; }  // h^2 k per dof in contact
  const Eigen::VectorXd& force() const { return force_; }        // k depth - h k v there

  // The step's outcome (x, v) with every node below the plane put on it.
  void project(Eigen::VectorXd& x, Eigen::VectorXd& v) const;

 private:
  FloorPlane floor_;
  int up_;  // the axis of the plane's normal
  double stiffness_, friction_;
  Eigen::VectorXd diagonal_, force_;
};

}  // namespace tetskin
