// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "tetskin/core/Geometry.h"

namespace tetskin {
namespace {

const Eigen::Vector3d O(0, 0, 0), X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

TEST(Geometry, NearestPointIsTheClosestRowAndTheFirstOnTies) {
  Points3 p(4, 3);
  p << 0, 0, 0, 1, 0, 0, 0, 2, 0, 1, 0, 0;
  EXPECT_EQ(nearestPoint(p, {0.9, 0.1, 0}), 1);  // row 3 is as near: the lower wins
  EXPECT_EQ(nearestPoint(p, {0, 1.5, 0}), 2);
  EXPECT_EQ(nearestPoint(p, {-5, 0, 0}), 0);
  EXPECT_EQ(nearestPoint(Points3(), {0, 0, 0}), -1);
}

// Faces included, rows in order; an empty box holds none.
TEST(Geometry, PointsInBoxIncludeItsFaces) {
  Points3 points(4, 3);
  points << 0, 0, 0, 1, 1, 1, 0.5, 2, 0.5, 1.0000001, 0.5, 0.5;
  BoundingBox box;
  box.min = {0, 0, 0};
  box.max = {1, 1, 1};
  EXPECT_EQ(pointsInBox(points, box), (std::vector<int>{0, 1}));
  box.max.y() = 2;
  EXPECT_EQ(pointsInBox(points, box), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(pointsInBox(points, BoundingBox{}).empty());
}

TEST(Geometry, UnitTetrahedronHasVolumeOneSixthAndSignFollowsOrientation) {
  EXPECT_DOUBLE_EQ(signedTetVolume(O, X, Y, Z), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signedTetVolume(O, Y, X, Z), -1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signedTetVolume(O, X, 2 * X, Z), 0.0);
}

TEST(Geometry, VolumeScalesWithTheCubeOfTheSize) {
  EXPECT_NEAR(signedTetVolume(3 * O, 3 * X, 3 * Y, 3 * Z), 27.0 / 6.0, 1e-12);
}

TEST(Geometry, TriangleAreaAndUnitNormal) {
  EXPECT_DOUBLE_EQ(triangleArea(O, 2 * X, 2 * Y), 2.0);
  EXPECT_TRUE(triangleNormal(O, X, Y).isApprox(Z));
  EXPECT_TRUE(triangleNormal(O, Y, X).isApprox(-Z));
  EXPECT_TRUE(triangleAreaVector(O, 2 * X, 2 * Y).isApprox(2 * Z));
}

TEST(Geometry, DegenerateTriangleHasZeroNormal) {
  EXPECT_EQ(triangleNormal(O, X, 2 * X), Eigen::Vector3d::Zero());
  EXPECT_EQ(triangleNormal(X, X, X), Eigen::Vector3d::Zero());
}

TEST(Geometry, BoundingBoxOfPoints) {
  Points3 p(3, 3);
  p << 1, 2, 3, -1, 5, 0, 4, -2, 1;
  const BoundingBox box = boundingBox(p);
  EXPECT_EQ(box.min, Eigen::Vector3d(-1, -2, 0));
  EXPECT_EQ(box.max, Eigen::Vector3d(4, 5, 3));
  EXPECT_DOUBLE_EQ(box.diagonal(), std::sqrt(25.0 + 49.0 + 9.0));
  EXPECT_EQ(box.center(), Eigen::Vector3d(1.5, 1.5, 1.5));
}

TEST(Geometry, EmptyBoundingBox) {
  const BoundingBox box = boundingBox(Points3(0, 3));
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.diagonal(), 0.0);
  BoundingBox grown;
  grown.extend(X);
  EXPECT_FALSE(grown.empty());
  EXPECT_EQ(grown.min, X);
}

// Every mesh's points pass through coordinateProblem: NaN and infinity, and
// magnitudes whose products would overflow, are named; the limit itself is
// accepted.
TEST(Geometry, BoxOverlapIsTheSharedShareOfTheUnion) {
  auto box = [](Eigen::Vector3d min, Eigen::Vector3d max) {
    BoundingBox b;
    b.min = min;
    b.max = max;
    return b;
  };
  const BoundingBox unit = box({0, 0, 0}, {1, 1, 1});
  EXPECT_DOUBLE_EQ(boxOverlap(unit, unit), 1.0);
  // Half a unit moved along x: 0.5 shared of 1.5 spanned.
  EXPECT_DOUBLE_EQ(boxOverlap(unit, box({0.5, 0, 0}, {1.5, 1, 1})), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(boxOverlap(box({0.5, 0, 0}, {1.5, 1, 1}), unit), 1.0 / 3.0);
  // Inside a box of 8 times the volume: 1/8.
  EXPECT_DOUBLE_EQ(boxOverlap(unit, box({0, 0, 0}, {2, 2, 2})), 0.125);
  EXPECT_DOUBLE_EQ(boxOverlap(unit, box({2, 0, 0}, {3, 1, 1})), 0.0);  // apart
  EXPECT_DOUBLE_EQ(boxOverlap(unit, box({1, 0, 0}, {2, 1, 1})), 0.0);  // touching
  EXPECT_DOUBLE_EQ(boxOverlap(unit, BoundingBox{}), 0.0);              // empty
  const BoundingBox flat = box({0, 0, 0}, {1, 1, 0});
  EXPECT_DOUBLE_EQ(boxOverlap(flat, flat), 1.0);
  EXPECT_DOUBLE_EQ(boxOverlap(flat, box({0, 0, 0}, {2, 1, 0})), 0.0);
}

TEST(Geometry, CoordinateProblemNamesNonFiniteAndHugeCoordinates) {
  EXPECT_EQ(coordinateProblem(Eigen::RowVector3d(1, -2, 3)), "");
  EXPECT_EQ(coordinateProblem(Eigen::RowVector3d(kMaxCoordinate, -kMaxCoordinate, 0)), "");
  EXPECT_EQ(coordinateProblem(Eigen::RowVector3d(0, std::nan(""), 0)),
            "has a non-finite coordinate");
  EXPECT_EQ(coordinateProblem(Eigen::RowVector3d(0, 0, -HUGE_VAL)), "has a non-finite coordinate");
  EXPECT_EQ(coordinateProblem(Eigen::RowVector3d(0, -2e31, 1e300)),
            "has a coordinate of magnitude 1e+300, beyond the largest accepted (1e+30); rescale "
            "the model");
}

}  // namespace
}  // namespace tetskin
