// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Coarser input levels of detail from one fine surface, because a 70k-triangle
// scan cannot give a 600-tetrahedron control mesh: TetGen keeps every input
// triangle on the boundary.

#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// Quadric decimation (VTK's vtkQuadricDecimation, volume preserving) to about
// `targetTriangles` triangles.
SurfaceMesh decimateSurface(const SurfaceMesh& surface, Index targetTriangles);

// Successively coarser copies, each with about `factor` times the triangles of
// the previous one, as long as they keep at least `minTriangles`; at most
// `maxCount` copies. The input itself is not included. The defaults reach
// 60 triangles (a control mesh of a few hundred elements) from up to 3.9M:
// a 75k-triangle scan stopped at 294 after 8 halvings, whose 2457 elements
// missed a 600-element target by 4x.
std::vector<SurfaceMesh> decimatedSeries(const SurfaceMesh& finest, double factor = 0.5,
                                         Index minTriangles = 60, int maxCount = 16);

}  // namespace tetskin
