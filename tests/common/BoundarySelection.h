// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Faces of a mesh's boundary chosen by their corners, for the tests that
// load or hold a side of a body (a beam's end, a plate's upper face).
// (Targets that include this link TetSkin::binding.)

#include <vector>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::test {

// The boundary faces of `mesh`, wound outward, whose three corners (node
// ids) all satisfy `keep(node)`.
template <class Keep>
Triangles boundaryFacesWhere(const TetMesh& mesh, Keep keep) {
  const BoundaryFaces boundary = boundaryFaces(mesh);
  std::vector<Index> chosen;
  for (Index f = 0; f < boundary.faces.rows(); ++f)
    if (keep(Index{boundary.faces(f, 0)}) && keep(Index{boundary.faces(f, 1)}) &&
        keep(Index{boundary.faces(f, 2)}))
      chosen.push_back(f);
  Triangles faces(static_cast<Index>(chosen.size()), 3);
  for (std::size_t k = 0; k < chosen.size(); ++k)
    faces.row(static_cast<Index>(k)) = boundary.faces.row(chosen[k]);
  return faces;
}

}  // namespace tetskin::test
