// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Binding a high-resolution surface to one level of the control mesh (report
// section 3): per surface vertex the control nodes, weights and offset that
// SurfaceDeformer applies each frame.

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

struct BindingOptions {
  BindingMethod method = BindingMethod::Closest;
  OffsetMode offset = OffsetMode::Normal;
  // Closest: boundary faces whose distance is within this (relative to the
  // control level's bounding-box diagonal) of the nearest count as equally
  // near; among them the face whose normal agrees with the surface normal
  // wins, then the larger smallest barycentric coordinate, then the lower id.
  double tieTolerance = 1e-6;
};

// Inputs:
//   surface  #V x 3 vertex positions and #F x 3 triangles (model units,
//            the control mesh's frame)
//   mesh     the dataset: #N x 3 rest node positions of every level
//   level    the control level bound to; < 0 counts from the finest
// Outputs:
//   per surface vertex (#V rows): 3 control node ids in the dataset's
//   numbering (4 for embed), their barycentric weights (summing to 1), the
//   offset along the normal (model units) and the distance to the level's
//   boundary. Throws Error for an empty or non-finite surface, or a level
//   without usable (non-degenerate) boundary faces.
SurfaceBinding bindSurface(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level,
                           const BindingOptions& options = {});

// The Closest method by testing every boundary face: the reference the fast
// search must equal exactly (tests, benchmark).
SurfaceBinding bindClosestBruteForce(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh,
                                     int level, const BindingOptions& options = {});

}  // namespace tetskin
