// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Shapes.h"

namespace tetskin::test {

TetMesh unitTetrahedron() {
  TetMesh m;
  m.nodes.resize(4, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.elements.resize(1, 4);
  m.elements << 0, 1, 2, 3;
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

}  // namespace tetskin::test
