// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/TetMesh.h"

#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

Eigen::Vector3d node(const Points3& nodes, int id) {
  return nodes.row(id).transpose();
}

}  // namespace

double elementVolume(const TetMesh& mesh, Index e) {
  const auto& t = mesh.elements;
  return signedTetVolume(node(mesh.nodes, t(e, 0)), node(mesh.nodes, t(e, 1)),
                         node(mesh.nodes, t(e, 2)), node(mesh.nodes, t(e, 3)));
}

double meshVolume(const TetMesh& mesh) {
  double sum = 0;
  for (Index e = 0; e < mesh.elementCount(); ++e) sum += elementVolume(mesh, e);
  return sum;
}

void validateTetMesh(const TetMesh& mesh, const std::string& name, bool requirePositiveVolume) {
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    const std::string problem = coordinateProblem(mesh.nodes.row(v));
    if (!problem.empty()) throw Error(name, 0, "node " + std::to_string(v) + " " + problem);
  }
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    for (int k = 0; k < 4; ++k) {
      const int id = mesh.elements(e, k);
      if (id < 0 || id >= mesh.nodeCount())
        throw Error(name, 0,
                    "element " + std::to_string(e) + " refers to node " + std::to_string(id) +
                        ", but the mesh has " + std::to_string(mesh.nodeCount()) + " nodes");
    }
    if (requirePositiveVolume) {
      const double volume = elementVolume(mesh, e);
      if (!(volume > 0.0))
        throw Error(name, 0,
                    "element " + std::to_string(e) + " has non-positive volume " +
                        formatNumber(volume) + " (inverted or degenerate)");
    }
  }
}

void validateLevels(const MultiLevelTetMesh& mesh, const std::string& name) {
  Index nextNode = 0;
  Index nextElement = 0;
  for (int k = 0; k < mesh.levelCount(); ++k) {
    const LevelRange& level = mesh.levels[k];
    const std::string where = "level " + std::to_string(k);
    if (level.firstNode != nextNode || level.firstElement != nextElement)
      throw Error(
          name, 0,
          where + " starts at node " + std::to_string(level.firstNode) + ", element " +
              std::to_string(level.firstElement) + ", but " +
              (k == 0 ? std::string("the first level must start at node 0, element 0")
                      : "level " + std::to_string(k - 1) + " ends before node " +
                            std::to_string(nextNode) + ", element " + std::to_string(nextElement)) +
              " (levels must be contiguous, coarsest first)");
    if (level.nodeCount <= 0 || level.elementCount <= 0)
      throw Error(name, 0, where + " has no nodes or no elements");
    nextNode += level.nodeCount;
    nextElement += level.elementCount;
    if (nextNode > mesh.nodes.rows() || nextElement > mesh.elements.rows())
      throw Error(name, 0, where + " reaches past the end of the node or element array");
    for (Index e = level.firstElement; e < nextElement; ++e) {
      for (int c = 0; c < 4; ++c) {
        const int id = mesh.elements(e, c);
        if (id < level.firstNode || id >= nextNode)
          throw Error(name, 0,
                      "element " + std::to_string(e) + " of " + where + " refers to node " +
                          std::to_string(id) + " outside the level's nodes [" +
                          std::to_string(level.firstNode) + ", " + std::to_string(nextNode) + ")");
      }
    }
  }
  if (nextNode != mesh.nodes.rows() || nextElement != mesh.elements.rows())
    throw Error(name, 0,
                "the levels cover " + std::to_string(nextNode) + " nodes and " +
                    std::to_string(nextElement) + " elements, but the mesh has " +
                    std::to_string(mesh.nodes.rows()) + " and " +
                    std::to_string(mesh.elements.rows()));
}

std::vector<Index> unreferencedNodes(const TetMesh& mesh) {
  std::vector<char> used(static_cast<std::size_t>(mesh.nodeCount()), 0);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int c = 0; c < 4; ++c) used[static_cast<std::size_t>(mesh.elements(e, c))] = 1;
  std::vector<Index> unused;
  for (Index v = 0; v < mesh.nodeCount(); ++v)
    if (!used[static_cast<std::size_t>(v)]) unused.push_back(v);
  return unused;
}

Index removeUnreferencedNodes(TetMesh& mesh) {
  const std::vector<Index> unused = unreferencedNodes(mesh);
  if (unused.empty()) return 0;
  std::vector<int> newId(static_cast<std::size_t>(mesh.nodeCount()), -1);
  Points3 kept(mesh.nodeCount() - static_cast<Index>(unused.size()), 3);
  std::size_t skip = 0;
  int next = 0;
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    if (skip < unused.size() && unused[skip] == v) {
      ++skip;
      continue;
    }
    kept.row(next) = mesh.nodes.row(v);
    newId[static_cast<std::size_t>(v)] = next++;
  }
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int c = 0; c < 4; ++c)
      mesh.elements(e, c) = newId[static_cast<std::size_t>(mesh.elements(e, c))];
  mesh.nodes = std::move(kept);
  return static_cast<Index>(unused.size());
}

Index orientElementsPositively(TetMesh& mesh) {
  Index flipped = 0;
  for (Index e = 0; e < mesh.elementCount(); ++e)
    if (elementVolume(mesh, e) < 0) {
      std::swap(mesh.elements(e, 2), mesh.elements(e, 3));
      ++flipped;
    }
  return flipped;
}

TetMesh extractLevel(const MultiLevelTetMesh& mesh, int level) {
  if (level < 0 || level >= mesh.levelCount())
    throw Error("level " + std::to_string(level) + " does not exist (the dataset has " +
                std::to_string(mesh.levelCount()) + " levels)");
  const LevelRange& r = mesh.levels[static_cast<std::size_t>(level)];
  TetMesh out;
  out.nodes = mesh.nodes.middleRows(r.firstNode, r.nodeCount);
  out.elements = mesh.elements.middleRows(r.firstElement, r.elementCount).array() -
                 static_cast<int>(r.firstNode);
  return out;
}

void appendLevel(MultiLevelTetMesh& mesh, const TetMesh& level) {
  LevelRange r;
  r.firstNode = mesh.nodes.rows();
  r.nodeCount = level.nodeCount();
  r.firstElement = mesh.elements.rows();
  r.elementCount = level.elementCount();
  mesh.nodes.conservativeResize(r.firstNode + r.nodeCount, 3);
  mesh.nodes.bottomRows(r.nodeCount) = level.nodes;
  mesh.elements.conservativeResize(r.firstElement + r.elementCount, 4);
  mesh.elements.bottomRows(r.elementCount) = level.elements.array() + static_cast<int>(r.firstNode);
  mesh.levels.push_back(r);
}

}  // namespace tetskin
