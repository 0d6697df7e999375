// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A triangulated surface: the high-resolution mesh that is bound to the
// control mesh, or an input of model generation.

#include <string>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/Types.h"

namespace tetskin {

struct SurfaceMesh {
  Points3 positions;    // #V x 3, model units
  Triangles triangles;  // #F x 3 vertex indices, counter-clockwise seen from outside
  Points3 normals;      // #V x 3 unit normals; empty (0 rows) when absent
  Points2 texcoords;    // #V x 2 (u, v); empty (0 rows) when absent

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
// The mean length of the triangles' edges (an edge of two triangles
// counted twice); 0 without triangles.
double meanEdgeLength(const SurfaceMesh& mesh);
// Signed volume the surface encloses (divergence theorem over its
// triangles): positive for a closed surface wound outward, negative for one
// wound inward; for an open surface it depends on the origin.
double enclosedVolume(const SurfaceMesh& mesh);

// Where a surface's smooth vertex normals (area-weighted sums of its
// triangles' normals, as bind and the deformation compute them) are
// missing: triangles of zero area (whose triangleNormal() is zero) and the
// vertices that no triangle of positive area touches (unreferenced ones
// included), whose normal is the zero vector: such a vertex is unlit when
// drawn. The counts and the first of each (-1 where none).
struct NormalGaps {
  Index zeroAreaTriangles = 0, firstZeroAreaTriangle = -1;
  Index verticesWithoutNormal = 0, firstVertexWithoutNormal = -1;
  bool empty() const { return zeroAreaTriangles == 0 && verticesWithoutNormal == 0; }
};
NormalGaps normalGaps(const SurfaceMesh& mesh);
// "1 triangle of zero area (first: triangle 3); 2 vertices without a
// normal, in no triangle of positive area (first: vertex 7)", the parts
// that apply (numbers from 0); empty when there are none.
std::string describe(const NormalGaps& gaps);

}  // namespace tetskin
