// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A force model of the body, as SOFA splits force fields from the ODE
// solver: the implicit step (ImplicitEuler) sums a list of them and knows
// none by name. A model with force f(x, v), stiffness K = -df/dx and
// damping D = -df/dv adds, for a step of length h from (x, v),
//
//   to the system's matrix    h D + h^2 K
//   to its right-hand side    h (f - h K v)
//
// and may decide rows of the system (held nodes), correct the step's
// outcome (a contact's projection), and report its force at any state
// (reactions), its potential energy and its contacts. Elasticity, gravity,
// mass damping, held and driven nodes and the floor are models; a new
// contact model is a new class here and one line where Simulation builds
// its list (doc/dev/extending.md).

#include <memory>
#include <string_view>
#include <vector>

#include "tetskin/core/Types.h"
#include "tetskin/simulation/CouplingSprings.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {

// The start of a step: positions and velocities (3n, internal node order),
// its length and its time (s).
struct StepState {
  const Eigen::VectorXd& x;
  const Eigen::VectorXd& v;
  double h;
  double t = 0;
  // A static solve's Newton system (Simulation::solveStatic): the world
  // stands still at t, and moving obstacles do not move over h.
  bool still = false;
};

// The step's system A dv = b as the models build it. `diagonal` starts as
// the lumped mass M (per dof) and `force` as the applied loads; each model
// adds its per-dof terms to `diagonal` (those of springs also to `springs`,
// which rediscretized coarse operators restrict) and its f - h K v to
// `force`; the matrix pass then writes A (the elastic model: its pattern
// with `diagonal` on the diagonal) and adds blocks to it; b = h force,
// after which the constraints decide their rows. Springs between nodes the
// pattern does not couple go to `coupling` (their diagonal blocks to A).
struct StepSystem {
  Eigen::VectorXd diagonal;  // per dof of A: M + h D + h^2 K of the diagonal models
  Eigen::VectorXd springs;   // the springs' share of `diagonal` (sized when hasSprings)
  bool hasSprings = false;
  Eigen::VectorXd force;  // f - h K v of every model, and the loads (N)
  SparseMatrix* A = nullptr;
  Eigen::VectorXd* b = nullptr;
  CouplingSprings coupling;  // h^2 s u u^T of such springs, less their diagonal blocks

  // Adds a spring's h^2 k at `dof` to the diagonal and to `springs`.
  void addSpring(Index dof, double value) {
    diagonal[dof] += value;
    springsSized()[dof] += value;
  }
  // `springs`, sized (zero) on first use.
  Eigen::VectorXd& springsSized() {
    if (!hasSprings) {
      springs.setZero(diagonal.size());
      hasSprings = true;
    }
    return springs;
  }
};

// How a coarser level's own FEM becomes a coarse operator of the step's
// system (rediscretized multigrid): terms.stiffnessScale K + terms.
// rotationScale K_rot + massScale M (+ the springs' diagonal, restricted).
struct CoarseDiscretization {
  double massScale = 1;
  CorotatedFem::SystemTerms terms;
};

class ForceModel {
 public:
  virtual ~ForceModel() = default;
  ForceModel() = default;
  ForceModel(const ForceModel&) = delete;
  ForceModel& operator=(const ForceModel&) = delete;

  // Its f - h K v at the step's start and its per-dof terms (h D + h^2 K
  // of a diagonal K and D) into `system`; returns the contacts it found.
  virtual int addForce(const StepState&, StepSystem&) { return 0; }
  // Writes (the elastic model, first in the list) or adds blocks of A.
  virtual void addMatrix(const StepState&, StepSystem&) {}
  // Decides rows of A dv = b (held and driven nodes), once A and b are
  // complete.
  virtual void constrain(const StepState&, StepSystem&) {}
  // Corrects the step's outcome (x, v).
  virtual void project(Eigen::VectorXd& /*x*/, Eigen::VectorXd& /*v*/) const {}

  // Its force f(x, v) added to `force` (the reactions balance these).
  virtual void addForceAt(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*v*/,
                          Eigen::VectorXd& /*force*/) const {}
  // Whether its force is a contact's (Simulation::contactForces sums
  // these models' addForceAt).
  virtual bool isContact() const { return false; }
  // Its potential energy at x (from the rest state) added to `energies`.
  virtual void addEnergy(const Eigen::VectorXd& /*x*/, Energies& /*energies*/) const {}
  // Its terms of a coarse operator of a step of length h.
  virtual void addCoarseTerms(double /*h*/, CoarseDiscretization&) const {}
};

// The sum of `models`' forces at (x, v) (addForceAt; of the contacts only,
// if `contactsOnly`).
inline Eigen::VectorXd sumOfForces(const std::vector<std::unique_ptr<ForceModel>>& models,
                                   const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                   bool contactsOnly = false) {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(x.size());
  for (const auto& model : models)
    if (!contactsOnly || model->isContact()) model->addForceAt(x, v, force);
  return force;
}

}  // namespace tetskin
