// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/fur/FurGeometry.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {

FurMesh shellMesh(const BoxTexturedSurface& box, const std::vector<float>& heights) {
  FurMesh m;
  const Index n = box.splitVertexCount();
  const auto copies = static_cast<Index>(heights.size());
  m.source.reserve(static_cast<std::size_t>(n * copies));
  m.height.reserve(static_cast<std::size_t>(n * copies));
  m.texcoords.resize(n * copies, 2);
  m.triangles.resize(box.triangles.rows() * copies, 3);
  for (Index c = 0; c < copies; ++c) {
    for (Index v = 0; v < n; ++v) {
      m.source.push_back(static_cast<int>(box.source[static_cast<std::size_t>(v)]));
      m.height.push_back(heights[static_cast<std::size_t>(c)]);
    }
    m.texcoords.middleRows(c * n, n) = box.texcoords;
    m.triangles.middleRows(c * box.triangles.rows(), box.triangles.rows()) =
        box.triangles.array() + static_cast<int>(c * n);
  }
  return m;
}

std::vector<float> shellHeights(int count) {
  std::vector<float> h(static_cast<std::size_t>(std::max(count, 0)));
  for (int s = 0; s < count; ++s)
    h[static_cast<std::size_t>(s)] = static_cast<float>(s + 1) / static_cast<float>(count);
  return h;
}

FurMesh finMesh(const Points3& positions, const Triangles& triangles, double tileSize,
                std::uint32_t seed) {
  // Unique undirected edges, in first-seen order (deterministic).
  std::unordered_map<std::uint64_t, int> seen;
  std::vector<std::pair<int, int>> edges;
  for (Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                       static_cast<std::uint32_t>(std::max(a, b));
      if (seen.emplace(key, static_cast<int>(edges.size())).second) edges.emplace_back(a, b);
    }
  FurMesh m;
  const auto e = static_cast<Index>(edges.size());
  m.source.resize(static_cast<std::size_t>(4 * e));
  m.height.resize(static_cast<std::size_t>(4 * e));
  m.texcoords.resize(4 * e, 2);
  m.triangles.resize(2 * e, 3);
  std::mt19937 random(seed);
  for (Index i = 0; i < e; ++i) {
    const auto [a, b] = edges[static_cast<std::size_t>(i)];
    const double row = static_cast<double>(random() >> 8) * (1.0 / 16777216.0);
    const double start = static_cast<double>(random() >> 8) * (1.0 / 16777216.0);
    const double span = (positions.row(b) - positions.row(a)).norm() / tileSize;
    const int corner[4] = {a, b, b, a};
    const float height[4] = {0, 0, 1, 1};
    const double s[4] = {start, start + span, start + span, start};
    for (int c = 0; c < 4; ++c) {
      const auto v = static_cast<std::size_t>(4 * i + c);
      m.source[v] = corner[c];
      m.height[v] = height[c];
      m.texcoords(static_cast<Index>(v), 0) = s[c];
      m.texcoords(static_cast<Index>(v), 1) = row;
    }
    const int base = static_cast<int>(4 * i);
    m.triangles.row(2 * i) << base, base + 1, base + 2;
    m.triangles.row(2 * i + 1) << base, base + 2, base + 3;
  }
  return m;
}

void furPoints(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals,
               const Points3& velocities, const FurMesh& mesh, double length,
               const FurDynamicsOptions& dynamics, Points3& out) {
  out.resize(mesh.vertexCount(), 3);
  furPoints(positions, normals, velocities, mesh, length, dynamics, Points3Ref(out));
}

void furPoints(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals,
               const Points3& velocities, const FurMesh& mesh, double length,
               const FurDynamicsOptions& dynamics, Points3Ref out) {
  const Index n = mesh.vertexCount();
  requireRows("fur points", out.rows(), n, "fur vertices");
  parallelFor<Index>(0, n, 4096, [&](const IndexRange<Index>& r) {
    for (Index i = r.begin(); i != r.end(); ++i) {
      const Index v = mesh.source[static_cast<std::size_t>(i)];
      const Eigen::Vector3d p = positions.row(v);
      out.row(i) = p + furShellOffset(normals.row(v), velocities.row(v),
                                      mesh.height[static_cast<std::size_t>(i)], length, dynamics);
    }
  });
}

void furNormals(const ConstPoints3Ref& normals, const FurMesh& mesh, Points3Ref out) {
  const Index n = mesh.vertexCount();
  requireRows("fur normals", out.rows(), n, "fur vertices");
  parallelFor<Index>(0, n, 8192, [&](const IndexRange<Index>& r) {
    for (Index i = r.begin(); i != r.end(); ++i)
      out.row(i) = normals.row(mesh.source[static_cast<std::size_t>(i)]);
  });
}

int adaptiveShellCount(double furPixels, int minShells, int maxShells) {
  minShells = std::clamp(minShells, 1, std::max(maxShells, 1));
  if (!std::isfinite(furPixels)) return maxShells;
  return std::clamp(static_cast<int>(std::ceil(furPixels)), minShells, maxShells);
}

}  // namespace tetskin
