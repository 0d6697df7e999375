// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Smooth vertex normals (report 4.2): every face normal, weighted by the face's
// area, is added onto its vertices, then each vertex normal is normalized.
// Computed as two parallel passes without atomics: face normals, then a gather
// over each vertex's incident faces (its one-ring).

#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// For each vertex, the triangles that use it (compressed rows).
struct VertexTriangleAdjacency {
  std::vector<int> offsets;    // vertexCount + 1 entries
  std::vector<int> triangles;  // triangles of vertex v: [offsets[v], offsets[v+1])
};

VertexTriangleAdjacency vertexTriangleAdjacency(const Triangles& triangles, Index vertexCount);

// Inputs:
//   positions    #V x 3 vertex positions
//   triangles    #F x 3 vertex ids
//   adjacency    vertexTriangleAdjacency(triangles, #V)
//   faceScratch  #F x 3, overwritten (the area-weighted face normals)
// Outputs:
//   normals      #V x 3 unit normals; the zero vector for a vertex with no
//                area around it. Nothing is allocated.
void computeVertexNormals(const ConstPoints3Ref& positions, const Triangles& triangles,
                          const VertexTriangleAdjacency& adjacency, Points3& faceScratch,
                          Points3Ref normals);

// Convenience for one-off use (allocates).
Points3 vertexNormals(const Points3& positions, const Triangles& triangles);

// The normals of `vertices` alone (ascending, no repeats), row i for
// vertices[i], bit for bit as vertexNormals gives them: one pass over the
// triangles, no adjacency and no per-vertex arrays, for a few vertices of a
// large surface (binding's ties).
Points3 vertexNormalsOf(const ConstPoints3Ref& positions, const Triangles& triangles,
                        const std::vector<Index>& vertices);

}  // namespace tetskin
