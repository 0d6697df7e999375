// SPDX-License-Identifier: AGPL-3.0-or-later
#include "NodeConstraints.h"

#include <utility>

namespace tetskin {

std::vector<char> dofsOf(const std::vector<char>& fixedNodes) {
  std::vector<char> dofs(3 * fixedNodes.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i] = fixedNodes[i / 3];
  return dofs;
}

NodeConstraints::NodeConstraints(const SparseMatrix& pattern)
    : pattern_(pattern),
      fixedDofs_(static_cast<std::size_t>(pattern.rows()), 0),
      prescribed_(Eigen::VectorXd::Zero(pattern.rows())) {}

void NodeConstraints::setFixedDofs(std::vector<char> fixedDofs) {
  fixedDofs_ = std::move(fixedDofs);
  rows_ = DirichletRows(pattern_, fixedDofs_);
  targetNodes_.clear();
}

std::vector<char> NodeConstraints::wholeNodes() const {
  std::vector<char> whole(fixedDofs_.size() / 3);
  for (std::size_t node = 0; node < whole.size(); ++node)
    whole[node] = isFixed(static_cast<Index>(node));
  return whole;
}

void NodeConstraints::setTargets(std::vector<int> nodes, Points3 targets) {
  targetNodes_ = std::move(nodes);
  targets_ = std::move(targets);
}

void NodeConstraints::impose(SparseMatrix& A, Eigen::VectorXd& b, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& v, double h, CouplingSprings* coupling) {
  prescribed_.setZero();
  for (std::size_t d = 0; d < fixedDofs_.size(); ++d)
    if (fixedDofs_[d]) prescribed_[static_cast<Index>(d)] = -v[static_cast<Index>(d)];
  for (std::size_t i = 0; i < targetNodes_.size(); ++i) {
    const Index node = targetNodes_[i];
    const Eigen::Vector3d target = targets_.row(static_cast<Index>(i)).transpose();
    prescribed_.segment<3>(3 * node) =
        (target - x.segment<3>(3 * node)) / h - v.segment<3>(3 * node);
  }
  rows_.apply(A, &b, &prescribed_);
  if (coupling && !coupling->empty()) coupling->eliminate(fixedDofs_, prescribed_, b);
}

void NodeConstraints::placeOnTargets(Eigen::VectorXd& x) const {
  for (std::size_t i = 0; i < targetNodes_.size(); ++i)
    x.segment<3>(3 * targetNodes_[i]) = targets_.row(static_cast<Index>(i)).transpose();
}

}  // namespace tetskin
