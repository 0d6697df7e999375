// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Fixed and driven nodes as Dirichlet conditions on the step's velocity
// change: a fixed node's dv stops it, a driven (kinematic) node's dv takes
// it to its target at the end of the step; the system gets identity rows
// and columns there (DirichletRows.h) and the prescribed dv moves to the
// right-hand side. Node numbers are the internal ones (NodeNumbering.h).
// A force model (ForceModel.h) without a force: it decides rows.

#include <vector>

#include "DirichletRows.h"
#include "ForceModel.h"

namespace tetskin {

// Per node of `fixedNodes` (a flag each), per dof.
std::vector<char> dofsOf(const std::vector<char>& fixedNodes);

class NodeConstraints : public ForceModel {
 public:
  // For systems of `pattern`'s shape (3 dofs per node).
  explicit NodeConstraints(const SparseMatrix& pattern);

  // One flag per node, 1 = fixed; drops the targets.
  void setFixed(const std::vector<char>& fixedNodes) { setFixedDofs(dofsOf(fixedNodes)); }
  // One flag per dof (a node held along some axes only); drops the targets.
  void setFixedDofs(std::vector<char> fixedDofs);
  // Whether all three of the node's dofs are held.
  bool isFixed(Index node) const {
    const auto d = 3 * static_cast<std::size_t>(node);
    return fixedDofs_[d] && fixedDofs_[d + 1] && fixedDofs_[d + 2];
  }
  const std::vector<char>& fixedDofs() const { return fixedDofs_; }
  // One flag per node: held along all three axes (what the solvers'
  // multigrid keeps out of its corrections).
  std::vector<char> wholeNodes() const;
  // Fixed nodes that must reach `targets` (a row each) at the end of the
  // next step; the caller checked that each is fixed.
  void setTargets(std::vector<int> nodes, Points3 targets);

  // Imposes the conditions of a step of length h from (x, v) on A dv = b.
  // (`coupling`, if given, loses the held nodes too.)
  void impose(SparseMatrix& A, Eigen::VectorXd& b, const Eigen::VectorXd& x,
              const Eigen::VectorXd& v, double h, CouplingSprings* coupling = nullptr);
  void constrain(const StepState& at, StepSystem& system) override {
    impose(*system.A, *system.b, at.x, at.v, at.h, &system.coupling);
  }
  // The driven nodes of a step's outcome exactly on their targets (free of
  // the solve's round-off).
  void placeOnTargets(Eigen::VectorXd& x) const;
  void project(Eigen::VectorXd& x, Eigen::VectorXd&) const override { placeOnTargets(x); }

 private:
  const SparseMatrix& pattern_;
  std::vector<char> fixedDofs_;
  DirichletRows rows_;
  std::vector<int> targetNodes_;
  Points3 targets_;
  Eigen::VectorXd prescribed_;  // dv of the fixed dofs
};

}  // namespace tetskin
