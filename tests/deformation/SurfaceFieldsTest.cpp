// SPDX-License-Identifier: AGPL-3.0-or-later
// The stress and strain carried to the skin, and the errors between two
// deformations of one surface: known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectError.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceComparison.h"
#include "tetskin/deformation/SurfaceFields.h"

namespace tetskin {
namespace {

// Two tetrahedra sharing the face (1, 2, 3): the first of volume 1/6, the
// second (apex at 3 units) of volume 1/2.
TetMesh twoTetrahedra() {
  TetMesh mesh;
  mesh.nodes.resize(5, 3);
  mesh.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 3, 3, 3;
  mesh.elements.resize(2, 4);
  mesh.elements << 0, 1, 2, 3, 1, 2, 3, 4;
  return mesh;
}

// Each node: the mean of its elements' values weighted by their volumes;
// a node of one element takes that element's value.
TEST(SurfaceFields, NodeMeansWeighElementsByTheirRestVolume) {
  const TetMesh mesh = twoTetrahedra();
  const double v0 = std::abs(elementVolume(mesh, 0)), v1 = std::abs(elementVolume(mesh, 1));
  ASSERT_NEAR(v0, 1.0 / 6, 1e-15);
  ASSERT_GT(v1, v0);
  const Eigen::VectorXd means = nodeMeans(mesh, Eigen::Vector2d(10, 40));
  ASSERT_EQ(means.size(), 5);
  EXPECT_DOUBLE_EQ(means[0], 10);
  EXPECT_DOUBLE_EQ(means[4], 40);
  for (int shared : {1, 2, 3}) EXPECT_DOUBLE_EQ(means[shared], (10 * v0 + 40 * v1) / (v0 + v1));
  EXPECT_EQ(test::errorText([&] { nodeMeans(mesh, Eigen::Vector3d(1, 2, 3)); }),
            "3 element values for a level of 2 elements");
}

// A vertex takes its control nodes' values weighted as it is bound; the
// ids are the dataset's, the values the level's (from its first node).
TEST(SurfaceFields, BoundValuesAreTheBindingWeightedNodeValues) {
  SurfaceBinding binding;
  binding.resize(2);
  binding.controlIds.row(0) << 11, 12, 13, -1;
  binding.weights.row(0) << 0.5, 0.25, 0.25, 0;
  binding.controlIds.row(1) << 10, 14, 12, -1;
  binding.weights.row(1) << 1, 0, 0, 0;
  const Eigen::VectorXd nodes = (Eigen::VectorXd(5) << 1, 2, 4, 8, 16).finished();
  const Eigen::VectorXd values = boundValues(binding, 10, nodes);
  ASSERT_EQ(values.size(), 2);
  EXPECT_DOUBLE_EQ(values[0], 0.5 * 2 + 0.25 * 4 + 0.25 * 8);
  EXPECT_DOUBLE_EQ(values[1], 1);
  // Embed bindings weigh four nodes.
  binding.method = BindingMethod::Embed;
  binding.controlIds.row(0) << 10, 11, 12, 14;
  binding.weights.row(0) << 0.25, 0.25, 0.25, 0.25;
  binding.controlIds(1, 3) = 13;
  EXPECT_DOUBLE_EQ(boundValues(binding, 10, nodes)[0], (1 + 2 + 4 + 16) / 4.0);
  EXPECT_EQ(test::errorText([&] { boundValues(binding, 11, nodes); }),
            "surface vertex 0 is bound to node 10, outside the level's 5 nodes from 11");
}

Points3 rows(std::initializer_list<Eigen::RowVector3d> list) {
  Points3 p(static_cast<Index>(list.size()), 3);
  Index i = 0;
  for (const Eigen::RowVector3d& row : list) p.row(i++) = row;
  return p;
}

TEST(SurfaceComparison, DistancesAndNormalAnglesOfKnownPairs) {
  const Points3 reference = rows({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 2}});
  const Points3 referenceNormals = rows({{0, 0, 1}, {0, 0, 1}, {0, 0, 2}, {1, 0, 0}});
  const Points3 moved = rows({{0, 0, 0}, {1, 3, 4}, {0, 1, 0}, {2, 2, 2}});
  // Same; 90 degrees; opposite (unnormalized); a vertex without a normal.
  const Points3 normals = rows({{0, 0, 1}, {0, 1, 0}, {0, 0, -5}, {0, 0, 0}});
  SurfaceErrors errors;
  surfaceErrors(moved, normals, reference, referenceNormals, errors);
  ASSERT_EQ(errors.distance.size(), 4);
  EXPECT_EQ(errors.distance[0], 0);
  EXPECT_DOUBLE_EQ(errors.distance[1], 5);
  EXPECT_EQ(errors.normalAngle[0], 0);
  EXPECT_NEAR(errors.normalAngle[1], 90, 1e-12);
  EXPECT_NEAR(errors.normalAngle[2], 180, 1e-12);
  EXPECT_EQ(errors.normalAngle[3], 0);
  // A tiny turn is resolved, not lost to rounding (acos would give 0 or
  // an error of a few 1e-7 degrees).
  const double turn = 1e-9;  // radians
  const Points3 turned = rows({{0, std::sin(turn), std::cos(turn)}});
  surfaceErrors(rows({{0, 0, 0}}), turned, rows({{0, 0, 0}}), rows({{0, 0, 1}}), errors);
  EXPECT_NEAR(errors.normalAngle[0], turn * 180 / M_PI, 1e-20);
  EXPECT_EQ(test::errorText([&] {
              surfaceErrors(moved, normals, reference.topRows(3), referenceNormals, errors);
            }),
            "surfaces compared: 4 positions, 4 normals against 3 and 4: not the same surface");
}

}  // namespace
}  // namespace tetskin
