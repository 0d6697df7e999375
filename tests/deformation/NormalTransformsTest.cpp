// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/NormalTransforms.h"

namespace tetskin {
namespace {

Eigen::Matrix3d transformOf(const NormalTransformRows& rows, Index v) {
  return Eigen::Map<const Eigen::Matrix3d>(rows.row(v).data());  // the columns, in order
}

Points3 affine(const Points3& rest, const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  Points3 out(rest.rows(), 3);
  for (Index v = 0; v < rest.rows(); ++v)
    out.row(v) = (A * rest.row(v).transpose() + b).transpose();
  return out;
}

// Under x -> A x + b every tetrahedron's cof(F) is cof(A), so is every
// node's mean: a rotation turns normals by itself, a stretch by its cofactor.
TEST(NormalTransforms, AffineDeformationsGiveTheirCofactorAtEveryNode) {
  const TetMesh grid = test::tetGrid(3, 2, 2, {3, 2, 2});
  const NodeNormalTransforms transforms(grid.elements, grid.nodes);
  NormalTransformRows rows(grid.nodeCount(), 9);
  transforms.compute(grid.nodes, rows);
  for (Index v = 0; v < grid.nodeCount(); ++v)
    EXPECT_TRUE(transformOf(rows, v).isApprox(Eigen::Matrix3d::Identity(), 1e-12)) << v;

  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  transforms.compute(affine(grid.nodes, R, {4, -1, 2}), rows);
  for (Index v = 0; v < grid.nodeCount(); ++v)
    EXPECT_TRUE(transformOf(rows, v).isApprox(R, 1e-12)) << v;

  Eigen::Matrix3d A;
  A << 2, 0.3, 0, 0, 0.5, 0.1, 0.2, 0, 1.5;
  const Eigen::Matrix3d cofactor = A.determinant() * A.inverse().transpose();
  transforms.compute(affine(grid.nodes, A, Eigen::Vector3d::Zero()), rows);
  for (Index v = 0; v < grid.nodeCount(); ++v)
    EXPECT_TRUE(transformOf(rows, v).isApprox(cofactor, 1e-12)) << v;
  // A stretched plane's normal is the cofactor's image of the rest one
  // (here the plane z = 0, its in-plane edges mapped by A).
  const Eigen::Vector3d n = (cofactor * Eigen::Vector3d::UnitZ()).normalized();
  EXPECT_NEAR(n.dot(A.col(0)), 0, 1e-12);
  EXPECT_NEAR(n.dot(A.col(1)), 0, 1e-12);
}

// Where the deformation is not affine, a node's transform is its
// tetrahedra's cof(F) weighted by rest volume; a node no tetrahedron uses
// gets zero.
TEST(NormalTransforms, ANodesTransformIsItsTetrahedraVolumeWeightedMean) {
  Points3 rest(6, 3);
  rest << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -2, 9, 9, 9;  // node 5 unused
  Tetrahedra tets(2, 4);
  tets << 0, 1, 2, 3, 0, 2, 1, 4;  // volumes 1/6 and 2/6
  const NodeNormalTransforms transforms(tets, rest);
  Points3 moved = rest;
  moved.row(3) << 0.2, 0.1, 1.5;  // deforms the first tetrahedron only
  NormalTransformRows rows(6, 9);
  transforms.compute(moved, rows);
  auto cof = [&](const Points3& x, Index t) {
    Eigen::Matrix3d d, D;
    for (int k = 0; k < 3; ++k) {
      d.col(k) = (x.row(tets(t, k + 1)) - x.row(tets(t, 0))).transpose();
      D.col(k) = (rest.row(tets(t, k + 1)) - rest.row(tets(t, 0))).transpose();
    }
    const Eigen::Matrix3d F = d * D.inverse();
    return Eigen::Matrix3d(F.determinant() * F.inverse().transpose());
  };
  const Eigen::Matrix3d first = cof(moved, 0), second = cof(moved, 1);
  EXPECT_TRUE(second.isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_TRUE(transformOf(rows, 3).isApprox(first, 1e-12));  // in the first only
  EXPECT_TRUE(transformOf(rows, 4).isApprox(second, 1e-12));
  const Eigen::Matrix3d shared = (1 * first + 2 * second) / 3;
  for (Index v : {0, 1, 2}) EXPECT_TRUE(transformOf(rows, v).isApprox(shared, 1e-12)) << v;
  EXPECT_EQ(rows.row(5).norm(), 0.0);

  // Turned inside out, the first tetrahedron still turns the normal of its
  // face 0 1 3 into that face's deformed (x1 - x0) x (x3 - x0): cof(F) keeps
  // a normal's side, which now points into the tetrahedron.
  Points3 inverted = rest;
  inverted.row(3) << 0, 0, -1;
  transforms.compute(inverted, rows);
  const Eigen::Vector3d restNormal = Eigen::Vector3d::UnitX().cross(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d deformedNormal = Eigen::Vector3d::UnitX().cross(-Eigen::Vector3d::UnitZ());
  EXPECT_TRUE((transformOf(rows, 3) * restNormal).isApprox(deformedNormal, 1e-12));
}

TEST(NormalTransforms, BadMeshesAndSizesAreErrors) {
  Points3 rest(4, 3);
  rest << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Tetrahedra flipped(1, 4);
  flipped << 0, 2, 1, 3;
  EXPECT_THROW(NodeNormalTransforms(flipped, rest), Error);
  Tetrahedra outside(1, 4);
  outside << 0, 1, 2, 4;
  EXPECT_THROW(NodeNormalTransforms(outside, rest), Error);
  Tetrahedra tet(1, 4);
  tet << 0, 1, 2, 3;
  const NodeNormalTransforms transforms(tet, rest);
  NormalTransformRows rows(4, 9), fewer(3, 9);
  EXPECT_THROW(transforms.compute(rest.topRows(3), rows), Error);
  EXPECT_THROW(transforms.compute(rest, fewer), Error);
}

}  // namespace
}  // namespace tetskin
