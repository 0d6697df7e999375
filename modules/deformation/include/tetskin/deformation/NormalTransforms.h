// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Smooth normal transforms of a deformed tetrahedral mesh, one per node: how
// gpu-1pass turns an embedded surface's rest normals (embed bindings).
//
// A tetrahedron t turns normals by cof(F_t) = det(F_t) F_t^-T, F_t = d_t
// D_t^-1 its deformation gradient (d, D its deformed and rest edges as
// columns): F^-T up to a positive scale, and it keeps a normal's side
// through an inversion. Taken per tetrahedron, the shading shows the
// tetrahedra's faces wherever the deformation is not affine. Node v's
// transform is instead the rest-volume-weighted mean over its tetrahedra,
//   G_v = sum_t V_t cof(F_t) / sum_t V_t = sum_t cof(d_t) D_t^T / (6 sum_t V_t),
// and a surface vertex interpolates the G of its tetrahedron's four nodes
// with its barycentric weights: continuous across the tetrahedra, and exact
// (G = cof(A)) under any affine deformation x -> A x + b, rigid ones included.

#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

// One 3x3 transform per node: its three columns, 9 numbers a row.
using NormalTransformRows = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>;

class NodeNormalTransforms {
 public:
  // `tets` index rows of `rest` (e.g. one level's tetrahedra in the whole
  // dataset's numbering); each must have a positive rest volume
  // (validateTetMesh's Error names the first element that does not, or
  // that names a node `rest` lacks). Nodes no tetrahedron uses get the zero
  // transform.
  NodeNormalTransforms(const Tetrahedra& tets, const ConstPoints3Ref& rest);

  Index nodeCount() const { return static_cast<Index>(inverseVolumeSums_.size()); }

  // G_v for the nodes at `deformed` (nodeCount() rows) into `out` (as many
  // rows; nothing is allocated). Throws Error for a wrong row count.
  void compute(const ConstPoints3Ref& deformed, Eigen::Ref<NormalTransformRows> out) const;

 private:
  Tetrahedra tets_;
  std::vector<Eigen::Matrix3d> restEdgesTransposed_;  // D_t^T per tetrahedron
  std::vector<double> inverseVolumeSums_;             // 1 / (6 sum_t V_t) per node; 0: unused
};

}  // namespace tetskin
