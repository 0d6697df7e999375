// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A surface's edges and the triangles on each: shared by repair and nesting.

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// One key per undirected edge.
inline std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// For every undirected edge, the triangles using it.
inline std::unordered_map<std::uint64_t, std::vector<int>> edgeTriangles(const SurfaceMesh& mesh) {
  std::unordered_map<std::uint64_t, std::vector<int>> edges;
  edges.reserve(static_cast<std::size_t>(mesh.triangleCount()) * 2);
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      edges[edgeKey(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3))].push_back(
          static_cast<int>(t));
  return edges;
}

}  // namespace tetskin
