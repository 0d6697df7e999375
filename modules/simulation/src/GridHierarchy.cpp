// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/GridHierarchy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "NodeNumbering.h"
#include "tetskin/core/Error.h"

namespace tetskin {

namespace {

// A lattice node (i, j, k), 0 <= i, j, k < 2^21, packed so that the keys
// sort as (k, j, i): the nodes of a level numbered along x, then y, then z,
// neighbours close in memory for the sweeps.
using Key = std::uint64_t;
constexpr int kBits = 21;
constexpr std::int64_t kLatticeLimit = std::int64_t(1) << kBits;

Key keyOf(const Eigen::Vector3i& node) {
  return Key(node.x()) | (Key(node.y()) << kBits) | (Key(node.z()) << (2 * kBits));
}

Eigen::Vector3i nodeOf(Key key) {
  const Key mask = (Key(1) << kBits) - 1;
  return {int(key & mask), int((key >> kBits) & mask), int(key >> (2 * kBits))};
}

struct Weight {
  Key node;
  double value;
};

// The Kuhn-triangulation weights of a point at lattice coordinates t (all
// >= 0): the cell's corner, then one step along each axis in the order of
// the point's local coordinates, largest first; zero weights left out.
int kuhnWeights(const Eigen::Vector3d& t, Weight weights[4]) {
  const Eigen::Vector3d cellCorner = t.array().floor();
  const Eigen::Vector3d local = t - cellCorner;
  int axes[3] = {0, 1, 2};
  std::sort(axes, axes + 3, [&](int a, int b) { return local[a] > local[b]; });
  Eigen::Vector3i corner = cellCorner.cast<int>();
  const double values[4] = {1 - local[axes[0]], local[axes[0]] - local[axes[1]],
                            local[axes[1]] - local[axes[2]], local[axes[2]]};
  int count = 0;
  for (int k = 0; k < 4; ++k) {
    if (k > 0) ++corner[axes[k - 1]];
    if (values[k] > 0) weights[count++] = {keyOf(corner), values[k]};
  }
  return count;
}

// Union-find over the (point, corner) weights of a level.
struct Components {
  std::vector<int> parent;
  explicit Components(std::size_t count) : parent(count) {
    for (std::size_t i = 0; i < count; ++i) parent[i] = static_cast<int>(i);
  }
  int find(int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      int& up = parent[static_cast<std::size_t>(i)];
      up = parent[static_cast<std::size_t>(up)];  // (path halving)
      i = up;
    }
    return i;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// One grid level over points given in its lattice units (row i: point i's
// lattice coordinates), `adjacency` their graph (nonzero (i, j): i and j
// are neighbours). A lattice node becomes one coarse node per connected
// piece of the points it weighs (the points in its support, joined by the
// graph's edges among them): an ear and the head beside it, or two legs in
// one cell, get coarse nodes of their own (as Nesme et al. 2009 keep the
// topology of embedded bodies), and the coarse level can move them apart.
// Every point still takes its cell's 4 Kuhn weights, so linear fields stay
// exact.
GridLevel gridLevel(const Eigen::MatrixX3d& latticePoints, double cellSize,
                    const Eigen::Vector3d& origin, const SparseMatrix& adjacency) {
  const std::size_t points = static_cast<std::size_t>(latticePoints.rows());
  std::vector<Weight> weights(points * 4);
  std::vector<int> counts(points);
  for (std::size_t p = 0; p < points; ++p)
    counts[p] = kuhnWeights(latticePoints.row(static_cast<Index>(p)).transpose(), &weights[4 * p]);
  // Points joined by an edge share their piece of every corner they both weigh.
  Components pieces(weights.size());
  for (int u = 0; u < adjacency.outerSize(); ++u)
    for (SparseMatrix::InnerIterator it(adjacency, u); it; ++it) {
      const int v = static_cast<int>(it.col());
      if (v <= u) continue;
      for (int a = 0; a < counts[static_cast<std::size_t>(u)]; ++a)
        for (int b = 0; b < counts[static_cast<std::size_t>(v)]; ++b)
          if (weights[4 * static_cast<std::size_t>(u) + a].node ==
              weights[4 * static_cast<std::size_t>(v) + b].node)
            pieces.unite(4 * u + a, 4 * v + b);
    }
  // The coarse node of each weight: (lattice node, piece); all of them, in
  // lattice order.
  std::vector<std::pair<Key, int>> nodeOfWeight(weights.size());
  std::vector<std::pair<Key, int>> nodes;
  nodes.reserve(weights.size());
  for (std::size_t p = 0; p < points; ++p)
    for (int k = 0; k < counts[p]; ++k) {
      const std::size_t w = 4 * p + static_cast<std::size_t>(k);
      nodeOfWeight[w] = {weights[w].node, pieces.find(static_cast<int>(w))};
      nodes.push_back(nodeOfWeight[w]);
    }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());

  GridLevel level;
  level.cellSize = cellSize;
  level.lattice.resize(static_cast<Index>(nodes.size()), 3);
  level.nodes.resize(static_cast<Index>(nodes.size()), 3);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Eigen::Vector3i node = nodeOf(nodes[n].first);
    level.lattice.row(static_cast<Index>(n)) = node.transpose();
    level.nodes.row(static_cast<Index>(n)) = (origin + cellSize * node.cast<double>()).transpose();
  }
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(weights.size());
  for (std::size_t p = 0; p < points; ++p)
    for (int k = 0; k < counts[p]; ++k) {
      const std::size_t w = 4 * p + static_cast<std::size_t>(k);
      const auto column =
          std::lower_bound(nodes.begin(), nodes.end(), nodeOfWeight[w]) - nodes.begin();
      triplets.emplace_back(static_cast<int>(p), static_cast<int>(column), weights[w].value);
    }
  level.prolongation.resize(latticePoints.rows(), static_cast<Index>(nodes.size()));
  level.prolongation.setFromTriplets(triplets.begin(), triplets.end());
  return level;
}

// The mesh's node graph (meshNodeNeighbours) as a sparse pattern, for the
// coarse levels' graphs (coarseAdjacency).
SparseMatrix meshAdjacency(const TetMesh& mesh) {
  const std::vector<std::vector<int>> neighbours = meshNodeNeighbours(mesh);
  SparseMatrix adjacency(mesh.nodeCount(), mesh.nodeCount());
  std::vector<int> sizes;
  for (const std::vector<int>& list : neighbours) sizes.push_back(static_cast<int>(list.size()));
  adjacency.reserve(sizes);
  for (std::size_t v = 0; v < neighbours.size(); ++v)
    for (int u : neighbours[v]) adjacency.insert(static_cast<Index>(v), u) = 1.0;
  adjacency.makeCompressed();
  return adjacency;
}

// A coarse level's graph: coarse nodes whose supports hold the same or
// neighbouring finer nodes (the pattern of P^T (G + I) P).
SparseMatrix coarseAdjacency(const SparseMatrix& finer, const SparseMatrix& prolongation) {
  // (G + I as a sum: coeffRef on a compressed matrix inserts each missing
  // diagonal entry by moving every entry after it, which took about 20 s at
  // the 109k-element level's 23k nodes. The values are positive, so the sum
  // keeps the pattern of both.)
  SparseMatrix identity(finer.rows(), finer.cols());
  identity.setIdentity();
  const SparseMatrix joined = finer + identity;
  SparseMatrix pattern = prolongation;
  pattern.coeffs().setOnes();
  return SparseMatrix(SparseMatrix(pattern.transpose()) * joined * pattern);
}

}  // namespace

std::vector<SparseMatrix> GridHierarchy::prolongations() const {
  std::vector<SparseMatrix> result;
  for (const GridLevel& level : levels) result.push_back(level.prolongation);
  return result;
}

GridHierarchy enclosingGrids(const TetMesh& mesh, const GridHierarchyOptions& options) {
  if (options.coarsening <= 1) throw Error("grid hierarchy: the coarsening must be above 1");
  GridHierarchy hierarchy;
  const Points3& meshNodes = mesh.nodes;
  const Index count = meshNodes.rows();
  if (count <= options.coarsestNodes || options.maxLevels < 1) return hierarchy;
  if (!meshNodes.allFinite()) throw Error("grid hierarchy: a mesh node is not finite");
  const Eigen::Vector3d low = meshNodes.colwise().minCoeff().transpose();
  const Eigen::Vector3d extent = meshNodes.colwise().maxCoeff().transpose() - low;
  const double target = static_cast<double>(count) / options.coarsening;
  SparseMatrix adjacency = meshAdjacency(mesh);

  // Level 1's cell: from the box's volume as if the body filled it, then
  // corrected by the cube root of the node count it gave, a few times
  // (the count falls roughly with the cube of the cell size).
  const double size = std::max(extent.maxCoeff(), 1e-300);
  double cellSize = std::cbrt(std::max(extent.prod(), 1e-6 * size * size * size) / target);
  GridLevel first;
  for (int attempt = 0; attempt < 8; ++attempt) {
    cellSize = std::max(cellSize, size * 1e-6);  // (keeps the lattice within its key bits)
    hierarchy.origin = low - Eigen::Vector3d::Constant(0.5 * cellSize);
    const Eigen::MatrixX3d lattice =
        (meshNodes.rowwise() - hierarchy.origin.transpose()) / cellSize;
    first = gridLevel(lattice, cellSize, hierarchy.origin, adjacency);
    const double ratio = static_cast<double>(first.nodes.rows()) / target;
    if (std::abs(ratio - 1) < 0.05) break;
    cellSize *= std::cbrt(ratio);
  }
  if (first.lattice.maxCoeff() >= kLatticeLimit)
    throw Error("grid hierarchy: the mesh is too elongated for a grid of its nodes' spacing");
  if (first.nodes.rows() >= count) return hierarchy;  // no coarser than the mesh itself
  hierarchy.levels.push_back(std::move(first));

  // Further levels: the same lattice at twice the spacing.
  while (hierarchy.levels.back().nodes.rows() > options.coarsestNodes &&
         static_cast<int>(hierarchy.levels.size()) < options.maxLevels) {
    const GridLevel& finer = hierarchy.levels.back();
    adjacency = coarseAdjacency(adjacency, finer.prolongation);
    GridLevel next = gridLevel(finer.lattice.cast<double>() / 2, 2 * finer.cellSize,
                               hierarchy.origin, adjacency);
    // A level that hardly coarsens (a thin sheet one cell thick, say) is
    // not worth its cost: stop before it.
    if (next.nodes.rows() * 2 > finer.nodes.rows()) break;
    hierarchy.levels.push_back(std::move(next));
  }
  return hierarchy;
}

}  // namespace tetskin
