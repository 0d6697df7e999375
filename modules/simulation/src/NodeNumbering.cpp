// SPDX-License-Identifier: AGPL-3.0-or-later
#include "NodeNumbering.h"

#include <algorithm>

#include "NodeOrder.h"

namespace tetskin {
namespace {

// The mesh's nodes breadth first along its edges (internal -> mesh id),
// after checking the mesh.
std::vector<int> meshNodeOrder(const TetMesh& mesh, const std::string& name) {
  validateTetMesh(mesh, name, /*requirePositiveVolume=*/true);
  const std::vector<std::vector<int>> neighbours = meshNodeNeighbours(mesh);
  return breadthFirstOrder(static_cast<int>(neighbours.size()), [&](int v, auto&& visit) {
    for (int u : neighbours[static_cast<std::size_t>(v)]) visit(u);
  });
}

}  // namespace

std::vector<std::vector<int>> meshNodeNeighbours(const TetMesh& mesh) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(mesh.nodeCount()));
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j)
          neighbours[static_cast<std::size_t>(mesh.elements(e, i))].push_back(mesh.elements(e, j));
  for (std::vector<int>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

NodeNumbering::NodeNumbering(const TetMesh& mesh, const std::string& name)
    : order_(meshNodeOrder(mesh, name)), rank_(order_.size()) {
  for (std::size_t i = 0; i < order_.size(); ++i)
    rank_[static_cast<std::size_t>(order_[i])] = static_cast<int>(i);
}

TetMesh NodeNumbering::renumbered(const TetMesh& mesh) const {
  TetMesh result;
  result.nodes.resize(mesh.nodeCount(), 3);
  for (Index i = 0; i < mesh.nodeCount(); ++i) result.nodes.row(i) = mesh.nodes.row(outside(i));
  result.elements.resize(mesh.elementCount(), 4);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 4; ++k) result.elements(e, k) = internal(mesh.elements(e, k));
  return result;
}

Eigen::VectorXd NodeNumbering::toInternal(const Points3& perNode) const {
  Eigen::VectorXd result(3 * perNode.rows());
  for (std::size_t i = 0; i < order_.size(); ++i)
    result.segment<3>(3 * static_cast<Index>(i)) = perNode.row(order_[i]).transpose();
  return result;
}

Points3 NodeNumbering::toOutside(const Eigen::VectorXd& internal) const {
  Points3 result(nodeCount(), 3);
  for (std::size_t i = 0; i < order_.size(); ++i)
    result.row(order_[i]) = internal.segment<3>(3 * static_cast<Index>(i)).transpose();
  return result;
}

TetMesh renumberedBreadthFirst(const TetMesh& mesh, const std::string& name) {
  return NodeNumbering(mesh, name).renumbered(mesh);
}

std::string levelName(const std::string& datasetName, int level) {
  const std::string name = "level " + std::to_string(level);
  return datasetName.empty() ? name : datasetName + ": " + name;
}

}  // namespace tetskin
