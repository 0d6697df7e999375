// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/deformation/NormalTransforms.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {
namespace {

// The edges X_1 - X_0, X_2 - X_0, X_3 - X_0 of tetrahedron `t` as columns.
Eigen::Matrix3d edges(const Tetrahedra& tets, Index t, const ConstPoints3Ref& x) {
  Eigen::Matrix3d e;
  for (int k = 0; k < 3; ++k) e.col(k) = (x.row(tets(t, k + 1)) - x.row(tets(t, 0))).transpose();
  return e;
}

}  // namespace

NodeNormalTransforms::NodeNormalTransforms(const Tetrahedra& tets, const ConstPoints3Ref& rest)
    : tets_(tets),
      restEdgesTransposed_(static_cast<std::size_t>(tets.rows())),
      inverseVolumeSums_(static_cast<std::size_t>(rest.rows()), 0.0) {
  // Node ids in range, positive volumes (the mesh's one check; a copy of
  // the rest rows, once).
  validateTetMesh(TetMesh{Points3(rest), tets}, "normal transforms");
  for (Index t = 0; t < tets.rows(); ++t) {
    const Eigen::Matrix3d D = edges(tets, t, rest);
    const double sixVolumes = D.determinant();
    restEdgesTransposed_[static_cast<std::size_t>(t)] = D.transpose();
    for (int k = 0; k < 4; ++k)
      inverseVolumeSums_[static_cast<std::size_t>(tets(t, k))] += sixVolumes;
  }
  for (double& sum : inverseVolumeSums_) sum = sum > 0 ? 1 / sum : 0;
}

void NodeNormalTransforms::compute(const ConstPoints3Ref& deformed,
                                   Eigen::Ref<NormalTransformRows> out) const {
  requireRows("normal transforms: positions", deformed.rows(), nodeCount(), "nodes");
  requireRows("normal transforms: output", out.rows(), nodeCount(), "nodes");
  out.setZero();
  for (Index t = 0; t < tets_.rows(); ++t) {
    const Eigen::Matrix3d d = edges(tets_, t, deformed);
    // cof(d): its columns are the cross products of d's columns.
    Eigen::Matrix3d cofactor;
    cofactor.col(0) = d.col(1).cross(d.col(2));
    cofactor.col(1) = d.col(2).cross(d.col(0));
    cofactor.col(2) = d.col(0).cross(d.col(1));
    const Eigen::Matrix3d weighted = cofactor * restEdgesTransposed_[static_cast<std::size_t>(t)];
    const Eigen::Map<const Eigen::Matrix<double, 1, 9>> flat(weighted.data());  // column-major
    for (int k = 0; k < 4; ++k) out.row(tets_(t, k)) += flat;
  }
  for (Index v = 0; v < out.rows(); ++v)
    out.row(v) *= inverseVolumeSums_[static_cast<std::size_t>(v)];
}

}  // namespace tetskin
