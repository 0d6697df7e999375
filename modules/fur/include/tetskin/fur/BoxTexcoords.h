// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The report's "box texture coordinates" for fur (section 5): every triangle
// takes the planar coordinates of the cube side its normal faces most, so the
// fur texture is nowhere stretched by more than the tilt of a face against
// its side. A vertex has one coordinate pair, so a vertex whose triangles face
// different sides is split into one copy per side; `source` maps every copy
// back, and anything per vertex that must stay continuous (positions, the
// normals the shells are extruded along) is gathered through it from the
// unsplit surface, which stitches the seams shut.

#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// Cube sides: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
int dominantSide(const Eigen::Vector3d& normal);

struct BoxTexturedSurface {
  Triangles triangles;        // over the split vertices, same order as the input's
  std::vector<Index> source;  // split vertex -> vertex of the input surface
  Points2 texcoords;          // per split vertex, in texture tiles
  std::vector<int> sides;     // per triangle, its cube side
  Index splitVertexCount() const { return static_cast<Index>(source.size()); }
};

// `tileSize`: model units one texture tile spans (> 0). Coordinates are
// measured from the lowest corner of the positions' bounding box, so a
// moved surface keeps its texture coordinates. Degenerate triangles (no
// normal) take side 0.
BoxTexturedSurface boxTexcoords(const Points3& positions, const Triangles& triangles,
                                double tileSize);

// out.row(i) = values.row(source[i]): the unsplit surface's per-vertex data
// on the split vertices (resizes `out`).
void gatherSplit(const Points3& values, const std::vector<Index>& source, Points3& out);

}  // namespace tetskin
