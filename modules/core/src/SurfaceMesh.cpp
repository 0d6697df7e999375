// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/SurfaceMesh.h"

#include <vector>

#include "tetskin/core/Error.h"

namespace tetskin {

void validateSurface(const SurfaceMesh& mesh, const std::string& name) {
  const Index n = mesh.vertexCount();
  for (Index v = 0; v < n; ++v) {
    const std::string problem = coordinateProblem(mesh.positions.row(v));
    if (!problem.empty()) throw Error(name, 0, "vertex " + std::to_string(v) + " " + problem);
  }
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int id = mesh.triangles(t, k);
      if (id < 0 || id >= n)
        throw Error(name, 0,
                    "triangle " + std::to_string(t) + " refers to vertex " + std::to_string(id) +
                        ", but the mesh has " + std::to_string(n) + " vertices");
    }
  }
  if (mesh.hasNormals() && mesh.normals.rows() != n)
    throw Error(name, 0,
                "has " + std::to_string(mesh.normals.rows()) + " normals for " + std::to_string(n) +
                    " vertices");
  if (mesh.hasTexcoords() && mesh.texcoords.rows() != n)
    throw Error(name, 0,
                "has " + std::to_string(mesh.texcoords.rows()) + " texture coordinates for " +
                    std::to_string(n) + " vertices");
}

BoundingBox boundingBox(const SurfaceMesh& mesh) {
  return boundingBox(mesh.positions);
}

double surfaceArea(const SurfaceMesh& mesh) {
  double area = 0.0;
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    area += triangleArea(mesh.positions.row(mesh.triangles(t, 0)).transpose(),
                         mesh.positions.row(mesh.triangles(t, 1)).transpose(),
                         mesh.positions.row(mesh.triangles(t, 2)).transpose());
  }
  return area;
}

double meanEdgeLength(const SurfaceMesh& mesh) {
  if (mesh.triangleCount() == 0) return 0.0;
  double sum = 0.0;
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      sum += (mesh.positions.row(mesh.triangles(t, k)) -
              mesh.positions.row(mesh.triangles(t, (k + 1) % 3)))
                 .norm();
  return sum / (3.0 * static_cast<double>(mesh.triangleCount()));
}

double enclosedVolume(const SurfaceMesh& mesh) {
  if (mesh.vertexCount() == 0) return 0.0;
  // Each triangle spans a tetrahedron with the centroid of the vertices;
  // measuring from there rather than from the origin keeps the sum accurate
  // for a model far from the origin.
  const Eigen::Vector3d center = mesh.positions.colwise().mean().transpose();
  double volume = 0.0;
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    volume += signedTetVolume(center, mesh.positions.row(mesh.triangles(t, 0)).transpose(),
                              mesh.positions.row(mesh.triangles(t, 1)).transpose(),
                              mesh.positions.row(mesh.triangles(t, 2)).transpose());
  return volume;
}

NormalGaps normalGaps(const SurfaceMesh& mesh) {
  NormalGaps gaps;
  std::vector<char> hasNormal(static_cast<std::size_t>(mesh.vertexCount()), 0);
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    const auto corner = [&](int k) { return mesh.positions.row(mesh.triangles(t, k)).transpose(); };
    if (triangleNormal(corner(0), corner(1), corner(2)).isZero(0)) {
      if (gaps.zeroAreaTriangles++ == 0) gaps.firstZeroAreaTriangle = t;
      continue;
    }
    for (int k = 0; k < 3; ++k) hasNormal[static_cast<std::size_t>(mesh.triangles(t, k))] = 1;
  }
  for (Index v = 0; v < mesh.vertexCount(); ++v)
    if (!hasNormal[static_cast<std::size_t>(v)] && gaps.verticesWithoutNormal++ == 0)
      gaps.firstVertexWithoutNormal = v;
  return gaps;
}

std::string describe(const NormalGaps& gaps) {
  auto count = [](Index n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::string text;
  if (gaps.zeroAreaTriangles > 0)
    text = count(gaps.zeroAreaTriangles, "triangle", "triangles") +
           " of zero area (first: triangle " + std::to_string(gaps.firstZeroAreaTriangle) + ")";
  if (gaps.verticesWithoutNormal > 0)
    text += (text.empty() ? "" : "; ") + count(gaps.verticesWithoutNormal, "vertex", "vertices") +
            " without a normal, in no triangle of positive area (first: vertex " +
            std::to_string(gaps.firstVertexWithoutNormal) + ")";
  return text;
}

}  // namespace tetskin
