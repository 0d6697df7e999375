// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Springs of the step's system between nodes its pattern does not couple:
// a contact between two bodies' skins, or between far parts of one skin,
// ties the control nodes of a skin vertex to those of a triangle of
// another element, or of another body. Each spring is rank one, s u u^T
// with u = sum_j a_j e_j (x) n (nodes j, scalar weights a_j, one direction
// n), so it is kept as that (a few dozen numbers) instead of as up to 256
// 3x3 blocks. The system is A + C: A (the pattern's matrix) holds each
// spring's diagonal blocks s a_j^2 n n^T, where the preconditioners see
// them, and C the rest, sum s u u^T less those blocks, which CG adds to
// its products (conjugateGradient's `coupling`). Solves stay exact; a
// multigrid's coarse levels see the bodies uncoupled, and only precondition.

#include <span>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

class CouplingSprings {
 public:
  struct Entry {
    Index node;     // 3 node .. 3 node + 2 are its rows
    double weight;  // a_j
  };

  void clear();
  bool empty() const { return stiffness_.empty(); }
  std::size_t size() const { return stiffness_.size(); }
  // Adds s u u^T, u = sum_j entries[j].weight e_node (x) direction; a node
  // may appear once per spring.
  void add(double stiffness, const Eigen::Vector3d& direction, std::span<const Entry> entries);

  // y = C x on the nodes the springs touch (every other entry of y is left
  // as it is: a caller keeps y zero there).
  void product(const double* x, double* y) const;
  // The nodes the springs touch, each once.
  const std::vector<Index>& nodes() const { return touched_; }
  // Spring k: s, n and its entries (node, a_j).
  double stiffness(std::size_t k) const { return stiffness_[k]; }
  const Eigen::Vector3d& direction(std::size_t k) const { return direction_[k]; }
  std::span<const Entry> entries(std::size_t k) const {
    return {entries_.data() + starts_[k], starts_[k + 1] - starts_[k]};
  }

  // Keeps the springs `kept` says (one flag per spring, in the order they
  // were added), as eliminated: a solve again without the others.
  void keep(const std::vector<char>& kept);

  // Held nodes (one flag per dof; a node's three alike) leave the springs:
  // their rows and columns of C are dropped, and what their columns carried
  // at the prescribed dv (per dof) moves to the right-hand side b, as
  // DirichletRows does for A.
  void eliminate(const std::vector<char>& fixedDofs, const Eigen::VectorXd& prescribed,
                 Eigen::VectorXd& b);

 private:
  std::vector<double> stiffness_;
  std::vector<Eigen::Vector3d> direction_;
  std::vector<std::size_t> starts_{0};  // spring k's entries: starts_[k] .. starts_[k+1]-1
  std::vector<Entry> entries_;
  std::vector<Index> touched_;
  std::vector<char> isTouched_;  // per node
};

}  // namespace tetskin
