// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Transfer between non-nested tetrahedral levels (doc/dev/numerics.md, "Multigrid"):
// every fine node is located in a coarse element in rest coordinates and
// interpolated with its 4 barycentric weights. Nodes outside the coarse mesh
// take the nearest element with unclamped weights, so linear fields (and rigid
// motions) are still reproduced exactly. Rows sum to 1.

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

// Scalar prolongation: fine node count x coarse node count.
SparseMatrix nodalProlongation(const TetMesh& coarse, const Points3& fineNodes);

// The same for xyz degrees of freedom (each weight as a 3x3 identity block).
SparseMatrix expandToDofs(const SparseMatrix& nodal);

}  // namespace tetskin
