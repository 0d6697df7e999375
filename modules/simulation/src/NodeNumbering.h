// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A level's nodes renumbered breadth first along its edges (NodeOrder.h),
// for memory locality in the element pass and the solvers, and the
// conversions between the level's numbering (outside: the API's, the
// files') and the internal one.

#include <string>
#include <vector>

#include "tetskin/core/TetMesh.h"

namespace tetskin {

class NodeNumbering {
 public:
  // Checks `mesh` (positive element volumes; `name` says where it is in
  // errors) and numbers its nodes breadth first.
  NodeNumbering(const TetMesh& mesh, const std::string& name);

  Index nodeCount() const { return static_cast<Index>(order_.size()); }
  int outside(Index internalNode) const { return order_[static_cast<std::size_t>(internalNode)]; }
  int internal(int outsideNode) const { return rank_[static_cast<std::size_t>(outsideNode)]; }
  // internal node -> outside node
  const std::vector<int>& order() const { return order_; }

  // `mesh` (the one numbered) in the internal numbering.
  TetMesh renumbered(const TetMesh& mesh) const;
  // Per-node rows (outside numbering) as one internal xyz vector, and back.
  Eigen::VectorXd toInternal(const Points3& perNode) const;
  Points3 toOutside(const Eigen::VectorXd& internal) const;

 private:
  std::vector<int> order_;  // internal node -> outside node
  std::vector<int> rank_;   // outside node -> internal node
};

// `mesh` checked and renumbered breadth first (a coarser level of the
// multigrid, which keeps no numbering of its own outside).
TetMesh renumberedBreadthFirst(const TetMesh& mesh, const std::string& name);

// The mesh's node graph: each node's neighbours along the elements' edges,
// ascending, each once.
std::vector<std::vector<int>> meshNodeNeighbours(const TetMesh& mesh);

// Where a level is, for the errors of its checks: "bunny.json: level 0".
std::string levelName(const std::string& datasetName, int level);

}  // namespace tetskin
