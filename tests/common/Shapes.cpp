// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace tetskin::test {

TetMesh unitTetrahedron() {
  TetMesh m;
  m.nodes.resize(4, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.elements.resize(1, 4);
  m.elements << 0, 1, 2, 3;
  return m;
}

TetMesh tetGrid(int nx, int ny, int nz, const Eigen::Vector3d& size) {
  TetMesh m;
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  m.nodes.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.nodes.row(id(i, j, k)) << size.x() * i / nx, size.y() * j / ny, size.z() * k / nz;
  // Kuhn split: the 6 paths from corner 000 to 111 along the axes.
  static constexpr int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                       {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  m.elements.resize(6 * nx * ny * nz, 4);
  Index e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& path : kPaths) {
          int c[3] = {i, j, k};
          int ids[4];
          ids[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[path[s]];
            ids[s + 1] = id(c[0], c[1], c[2]);
          }
          m.elements.row(e) << ids[0], ids[1], ids[2], ids[3];
          if (elementVolume(m, e) < 0) std::swap(m.elements(e, 2), m.elements(e, 3));
          ++e;
        }
  return m;
}

SurfaceMesh box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  SurfaceMesh m;
  m.positions.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.positions.row(i) << (i & 1 ? hi.x() : lo.x()), (i & 2 ? hi.y() : lo.y()),
        (i & 4 ? hi.z() : lo.z());
  m.triangles.resize(12, 3);
  m.triangles << 0, 2, 1, 1, 2, 3,  // z = lo
      4, 5, 6, 5, 7, 6,             // z = hi
      0, 1, 4, 1, 5, 4,             // y = lo
      2, 6, 3, 3, 6, 7,             // y = hi
      0, 4, 2, 2, 4, 6,             // x = lo
      1, 3, 5, 3, 7, 5;             // x = hi
  return m;
}

SurfaceMesh sphere(const Eigen::Vector3d& center, double radius, int rings, int segments) {
  SurfaceMesh m;
  m.positions.resize(2 + (rings - 1) * segments, 3);
  m.positions.row(0) = (center + Eigen::Vector3d(0, radius, 0)).transpose();
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
      m.positions.row(1 + (i - 1) * segments + j) =
          (center + radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                             std::sin(theta) * std::sin(phi)))
              .transpose();
    }
  const int bottom = static_cast<int>(m.positions.rows()) - 1;
  m.positions.row(bottom) = (center - Eigen::Vector3d(0, radius, 0)).transpose();
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + j % segments; };
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j < segments; ++j) {
    triangles.push_back({0, ring(1, j + 1), ring(1, j)});
    triangles.push_back({bottom, ring(rings - 1, j), ring(rings - 1, j + 1)});
  }
  for (int i = 1; i < rings - 1; ++i)
    for (int j = 0; j < segments; ++j) {
      triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
  m.triangles.resize(static_cast<Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) m.triangles(static_cast<Index>(t), k) = triangles[t][k];
  return m;
}

SurfaceMesh merge(const SurfaceMesh& a, const SurfaceMesh& b) {
  SurfaceMesh m;
  m.positions.resize(a.vertexCount() + b.vertexCount(), 3);
  m.positions << a.positions, b.positions;
  m.triangles.resize(a.triangleCount() + b.triangleCount(), 3);
  m.triangles << a.triangles, b.triangles.array() + static_cast<int>(a.vertexCount());
  return m;
}

SurfaceMesh soup(const SurfaceMesh& mesh) {
  SurfaceMesh s;
  s.positions.resize(mesh.triangleCount() * 3, 3);
  s.triangles.resize(mesh.triangleCount(), 3);
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      s.positions.row(3 * t + k) = mesh.positions.row(mesh.triangles(t, k));
      s.triangles(t, k) = static_cast<int>(3 * t + k);
    }
  return s;
}

std::array<int, 3> innerFace(const TetMesh& mesh) {
  std::map<std::array<int, 3>, int> uses;
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face{};
      int k = 0;
      for (int c = 0; c < 4; ++c)
        if (c != skip) face[static_cast<std::size_t>(k++)] = mesh.elements(e, c);
      std::sort(face.begin(), face.end());
      if (++uses[face] == 2) return face;
    }
  throw std::runtime_error("the mesh has no inner face");
}

}  // namespace tetskin::test
