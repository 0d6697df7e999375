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
// `maxCount` copies. The input itself is not included.
std::vector<SurfaceMesh> decimatedSeries(const SurfaceMesh& finest, double factor = 0.5,
                                         Index minTriangles = 60, int maxCount = 8);

}  // namespace tetskin
