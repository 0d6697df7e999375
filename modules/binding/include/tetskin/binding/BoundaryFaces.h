// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The boundary of a tetrahedral mesh: faces used by exactly one element,
// oriented outward. Only these can carry the surface (report 3.2, step 1).

#include <vector>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

struct BoundaryFaces {
  Triangles faces;            // node ids (+ nodeOffset), counter-clockwise seen from outside
  std::vector<int> elements;  // the element each face belongs to
};

// Inputs:
//   mesh        #N x 3 nodes, #T x 4 positively oriented tetrahedra
//   nodeOffset  added to every id (the dataset's numbering when `mesh` is
//               one extracted level)
// Outputs:
//   #B x 3 faces wound counter-clockwise seen from outside, and the element
//   of each (#B).
BoundaryFaces boundaryFaces(const TetMesh& mesh, int nodeOffset = 0);

// The boundary as a surface of its own: the boundary faces over the nodes
// they use, renumbered in node order (inner nodes dropped). The winding
// comes from the elements' node order, not their positions, so a deformed
// copy of a mesh (a simulation frame) gives the surface wound as at rest.
SurfaceMesh boundarySurface(const TetMesh& mesh);

}  // namespace tetskin
