// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Transfer between non-nested tetrahedral levels (doc/dev/numerics.md, "Multigrid"):
// every fine node is located in a coarse element in rest coordinates and
// interpolated with its 4 barycentric weights. Nodes outside the coarse mesh
// take the nearest element with unclamped weights, so linear fields (and rigid
// motions) are still reproduced exactly. Rows sum to 1.

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

// Inputs: the coarse level (#Nc x 3 nodes, #Tc x 4 tetrahedra) and #Nf x 3
// fine nodes, in one frame (rest coordinates).
// Output: the scalar prolongation, #Nf x #Nc, 4 weights per row summing to 1.
SparseMatrix nodalProlongation(const TetMesh& coarse, const Points3& fineNodes);

// The same for xyz degrees of freedom: 3 #Nf x 3 #Nc, each weight as a 3x3
// identity block.
SparseMatrix expandToDofs(const SparseMatrix& nodal);

}  // namespace tetskin
