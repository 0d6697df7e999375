// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Locates points in a tetrahedral mesh: the element containing the point, or
// (outside the mesh) the nearest element, with the point's barycentric
// coordinates in it, unclamped (negative outside, so linear fields are still
// reproduced exactly). Used to embed surfaces in the control mesh and to
// transfer between non-nested multigrid levels. Queries are const and can run
// from many threads.

#include <Eigen/Core>

#include "tetskin/core/TetMesh.h"
#include "tetskin/spatial/AabbTree.h"

namespace tetskin {

struct TetLocation {
  int element = -1;
  Eigen::Vector4d barycentric = Eigen::Vector4d::Zero();  // sums to 1
  double squaredDistance = 0;                             // 0 inside the element
};

// Barycentric coordinates (4, summing to 1, unclamped) of the point p in
// element e of `mesh`.
Eigen::Vector4d tetBarycentric(const TetMesh& mesh, Index e, const Eigen::Vector3d& p);

class TetLocator {
 public:
  explicit TetLocator(const TetMesh& mesh);  // keeps a reference: `mesh` must outlive it
  // Input: a point (model units). Output: the containing element (the
  // lowest id on a shared face), else the nearest one, with p's
  // barycentric coordinates in it and its squared distance (0 inside).
  TetLocation locate(const Eigen::Vector3d& p) const;

 private:
  double squaredDistance(Index e, const Eigen::Vector3d& p) const;
  const TetMesh& mesh_;
  AabbTree tree_;
};

}  // namespace tetskin
