// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A triangulated surface: the high-resolution mesh that is bound to the
// control mesh, or an input of model generation.

#include <string>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/Types.h"

namespace tetskin {

struct SurfaceMesh {
  Points3 positions;    // one row per vertex
  Triangles triangles;  // vertex indices, counter-clockwise seen from outside
  Points3 normals;      // per vertex; empty (0 rows) when absent
  Points2 texcoords;    // per vertex; empty (0 rows) when absent

  Index vertexCount() const { return positions.rows(); }
  Index triangleCount() const { return triangles.rows(); }
  bool hasNormals() const { return normals.rows() > 0; }
  bool hasTexcoords() const { return texcoords.rows() > 0; }
};

// Throws Error naming `name` and the offending vertex or triangle when an index
// is out of range, a coordinate is not finite, or an attribute array does not
// have one row per vertex.
void validateSurface(const SurfaceMesh& mesh, const std::string& name);

BoundingBox boundingBox(const SurfaceMesh& mesh);
// Sum of the triangle areas.
double surfaceArea(const SurfaceMesh& mesh);

}  // namespace tetskin
