// SPDX-License-Identifier: AGPL-3.0-or-later
// Simulation::solveStatic: Newton's method on the static equations
// f(x) = f_el(x) + M g + f_ext + f_contact(x) = 0 at the free nodes.
//
// Each Newton system is an implicit-Euler step from rest (v = 0: no
// damping force, no friction) of a pseudo time step h so long that the
// mass only regularizes it: (M + h^2 K_T) dv = h f, dx = h dv, with M / h^2
// a millionth of the stiffest element diagonal. That keeps the force
// models, the held and driven nodes' rows and the solvers exactly as a
// step uses them, and it keeps the system positive definite where K_T
// alone is singular (a body resting on a floor is free to slide along
// it). Its fixed point is f(x) = 0 whatever h is. A backtracking line
// search on the energy's slope along the step takes the longest of 1,
// 1/2, ..., 1/64 over which the energy falls; when none does, h shrinks
// tenfold (a shorter, more gradient-like step) and the iteration tries
// again.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "BodyContact.h"
#include "ElasticForce.h"
#include "ImplicitEuler.h"
#include "NodeConstraints.h"
#include "NodeNumbering.h"
#include "ObstacleContact.h"
#include "SolverStack.h"
#include "SurfaceLoadForce.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {
namespace {

// The largest per-node norm of `force` along the dofs not flagged `held`
// (a node held along some axes counts along the others).
double largestFree(const Eigen::VectorXd& force, const std::vector<char>& held) {
  double largest = 0;
  for (std::size_t node = 0; 3 * node < held.size(); ++node) {
    double squared = 0;
    for (std::size_t k = 0; k < 3; ++k)
      if (!held[3 * node + k])
        squared +=
            force[static_cast<Index>(3 * node + k)] * force[static_cast<Index>(3 * node + k)];
    largest = std::max(largest, std::sqrt(squared));
  }
  return largest;
}

}  // namespace

StaticStats Simulation::solveStatic(double tolerance, int maxIterations) {
  if (!(tolerance > 0) || maxIterations < 1)
    throw Error("the static solve's tolerance must be positive and its iterations at least 1");
  Eigen::VectorXd x, external;
  double t = 0;
  {
    std::lock_guard lock(mutex_);
    x = x_;
    external = external_;
    t = time_;
  }
  const Index nodes = fem_.nodeCount();
  const std::vector<char>& held = constraints_->fixedDofs();  // per dof
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  Eigen::VectorXd load = external;
  if (surfaceLoadForce_) surfaceLoadForce_->addForceAt(x, Eigen::VectorXd::Zero(x.size()), load);
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  double total = 0;
  for (Index node = 0; node < nodes; ++node) {
    load.segment<3>(3 * node) += mass.segment<3>(3 * node).cwiseProduct(options_.gravity);
    net += load.segment<3>(3 * node);
    total += load.segment<3>(3 * node).norm();
  }
  if (fixedNodes_.empty() && axisNodes_.empty() && !obstacles_ && net.norm() > 1e-9 * total)
    throw Error(
        "there is no static equilibrium: the body is free (no held node, floor or "
        "obstacle) under a net load of " +
        commaSeparated(net) + " N; hold nodes or add a floor");
  if (obstacles_) obstacles_->forgetStep();
  if (bodyContact_) bodyContact_->forgetStep();

  // The pseudo time step: M / h^2 first 1e-10 of the stiffest element
  // diagonal at rest (a millionth kept a cantilever's first dozen steps
  // little more than steps of its dynamics); ten times longer after each
  // full Newton step, up to where M / h^2 is 1e-16 of it.
  double h = std::sqrt(mass.maxCoeff() / (1e-10 * stiffestRestDiagonal(fem_)));
  const double longest = 1e3 * h;
  // Driven nodes start on their targets: their elastic pull is part of the
  // first residual.
  constraints_->placeOnTargets(x);

  // The run's solver on the Newton systems: cg, or multigrid over the
  // solver's own grids (the dataset's levels and the automatic choice are
  // the dynamic run's business), from a zero guess each time.
  SimulationOptions linear = options_;
  if (linear.solver != SolverKind::ConjugateGradient) linear.solver = SolverKind::Multigrid;
  linear.coarseLevels = CoarseLevels::Grid;
  linear.coarseOperators = CoarseOperators::Galerkin;
  linear.coarseReuse = 1;
  linear.guessSolutions = 0;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(x.size());  // the velocities
  const auto residual = [&](const Eigen::VectorXd& at) {
    return Eigen::VectorXd(sumOfForces(models_, at, rest) + external);
  };

  StaticStats stats;
  stats.load = largestFree(load, held);
  SparseMatrix A = fem_.pattern();
  Eigen::VectorXd b, dv = rest, trial;
  // The Newton system at x with the present h (its assembly also poses the
  // contacts at t, which the residual's contact forces read).
  std::optional<ImplicitEuler> newton;
  const auto assemble = [&] {
    newton.emplace(h, mass, true);
    newton->assemble(models_, t, x, rest, external, A, b);
  };
  assemble();
  SolverStack solvers(MultiLevelTetMesh{}, 0, internal_, linear,
                      newton->coarseDiscretization(models_), "the static solve");
  solvers.setFixedNodes(constraints_->wholeNodes());
  Eigen::VectorXd r = residual(x);
  const double scale = std::max(stats.load, largestFree(r, held));
  // Below eps |x| K no Newton step can go: the elastic forces come from
  // positions, each rounded to eps of its size (the verification suite's
  // cantilevers, nodes at x ~ 10 m, stalled at 0.2 to 0.6 of it).
  stats.floor =
      std::numeric_limits<double>::epsilon() * x.cwiseAbs().maxCoeff() * stiffestRestDiagonal(fem_);
  const double enough = std::max(tolerance * scale, stats.floor);
  stats.residual = largestFree(r, held);
  stats.converged = stats.residual <= enough;
  int failures = 0;  // line searches in a row that found no decrease
  while (!stats.converged && stats.iterations < maxIterations && failures < 4) {
    ++stats.iterations;
    if (stats.iterations > 1) assemble();  // (x or h changed since: the first is assembled)
    StepStats ignored;
    dv.setZero();
    stats.linearIterations += solvers
                                  .solve(A, b, dv, stats.iterations - 1,
                                         {&x, newton->springs(), newton->coupling()}, ignored)
                                  .iterations;
    const Eigen::VectorXd dx = h * dv;
    // The line search on the energy E, without E itself: the residual is
    // -grad E, so dE/dalpha = -dx . r(x + alpha dx). A step is taken when
    // the trapezoid over its two ends says E fell: dx . (r(x) + r(trial))
    // > 0 (a full Newton step on a convex energy ends where the slope is
    // 0). (The residual's norm as the measure refused a cantilever's full
    // Newton steps from rest: its residual's peak grows before it falls.)
    const double slope = dx.dot(r);
    double taken = 0;  // the step length the line search took (0: none)
    for (double alpha = 1; alpha >= 1.0 / 64 && taken == 0 && slope > 0; alpha /= 2) {
      trial = x + alpha * dx;
      const Eigen::VectorXd trialResidual = residual(trial);
      if (trialResidual.allFinite() && dx.dot(trialResidual) + slope > 2e-4 * slope) {
        x = trial;
        r = trialResidual;
        taken = alpha;
      }
    }
    // No decrease: a shorter, more regularized step; after four in a row
    // the residual is at its round-off floor (or there is no equilibrium
    // near), and the best positions found stay.
    if (taken == 0) {
      h /= 10;
      ++failures;
      continue;
    }
    failures = 0;
    if (taken == 1) h = std::min(10 * h, longest);
    stats.residual = largestFree(r, held);
    stats.converged = stats.residual <= enough;
  }
  constraints_->placeOnTargets(x);
  std::lock_guard lock(mutex_);
  x_ = std::move(x);
  v_.setZero();
  acceleration_.setZero();
  dv_.setZero();
  return stats;
}

}  // namespace tetskin
