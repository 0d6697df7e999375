// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/SurfaceMesh.h"

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

}  // namespace tetskin
