// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Per-element values of a control level (its von Mises stress, its strain)
// carried to a bound surface, so a researcher sees where the skin is
// loaded: each node takes the mean of its elements' values weighted by
// their rest volumes, and each surface vertex the sum of its control nodes'
// values weighted by its binding weights. A vertex bound to a triangle thus
// sees the elements around the triangle's three corners, not only the one
// that holds the triangle: the colouring is continuous across triangles,
// and a vertex exactly on a corner takes that corner's mean.

#include <Eigen/Core>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

// Per node of `level` (its own numbering), the rest-volume-weighted mean of
// the values of the elements that hold it (0 for a node in none). Throws
// Error when `elementValues` has not one value per element.
Eigen::VectorXd nodeMeans(const TetMesh& level, const Eigen::VectorXd& elementValues);

// Per vertex of the surface `binding` binds, sum_i w_i nodeValues[id_i -
// firstNode]: `nodeValues` are of the level whose first node in the
// dataset's numbering (the binding's) is `firstNode`. Throws Error naming
// the vertex when one of its ids is outside the level.
Eigen::VectorXd boundValues(const SurfaceBinding& binding, Index firstNode,
                            const Eigen::VectorXd& nodeValues);

}  // namespace tetskin
