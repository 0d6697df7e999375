// SPDX-License-Identifier: AGPL-3.0-or-later
// An obstacle's placement and keyframed motion, its distances in the
// world (the floor's too), and the checks of its settings.
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/simulation/Obstacle.h"

namespace tetskin {
namespace {

Eigen::Quaterniond aboutZ(double degrees) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::UnitZ()));
}

Obstacle unitCube() {
  Obstacle o;
  o.name = "cube.obj";
  o.shape = std::make_shared<ClosedSurfaceDistance>(test::box({0, 0, 0}, {1, 1, 1}), o.name);
  return o;
}

TEST(Obstacle, KeyframesInterpolateAndHoldAtTheEnds) {
  Obstacle o = unitCube();
  o.placement.scale = 2;
  o.motion = {{0, {0, 0, 0}, aboutZ(0)}, {1, {2, 0, 0}, aboutZ(90)}, {3, {2, 4, 0}, aboutZ(90)}};
  const ObstaclePose half = o.poseAt(0.5);
  EXPECT_NEAR((half.translation - Eigen::Vector3d(1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(half.rotation.angularDistance(aboutZ(45)), 0, 1e-12);
  EXPECT_EQ(half.scale, 2);  // the placement's
  EXPECT_NEAR((o.poseAt(2).translation - Eigen::Vector3d(2, 2, 0)).norm(), 0, 1e-12);
  EXPECT_EQ(o.poseAt(-1).translation, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(o.poseAt(9).translation, Eigen::Vector3d(2, 4, 0));
  EXPECT_FALSE(obstacleProblem(o).has_value());
}

TEST(Obstacle, DistancesAreTheWorldsUnderTranslationRotationAndScale) {
  // The unit cube scaled by 2, turned 90 degrees about z and moved to
  // (10, 0, 0) occupies x in [8, 10], y in [0, 2], z in [0, 2].
  Obstacle o = unitCube();
  o.placement = {{10, 0, 0}, aboutZ(90), 2};
  const auto above = closestPointOf(o, 0, {9, 1, 5}, 10);
  ASSERT_TRUE(above.has_value());
  EXPECT_NEAR(above->distance, 3, 1e-12);
  EXPECT_NEAR((above->point - Eigen::Vector3d(9, 1, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR((above->normal - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-12);
  const auto inside = closestPointOf(o, 0, {8.3, 1, 1}, 10);
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->distance, -0.3, 1e-12);
  EXPECT_NEAR((inside->normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0, 1e-12);
  EXPECT_FALSE(closestPointOf(o, 0, {9, 1, 5}, 2.9).has_value());  // radius in world units
}

TEST(Obstacle, BadSettingsAreNamed) {
  Obstacle o = unitCube();
  o.kineticFriction = 0.6;
  EXPECT_EQ(*obstacleProblem(o),
            "cube.obj: friction must satisfy 0 <= kinetic <= static, got static 0.5 and kinetic "
            "0.6");
  o = unitCube();
  o.placement.scale = 0;
  EXPECT_EQ(*obstacleProblem(o), "cube.obj: the scale must be finite and positive, got 0");
  o = unitCube();
  o.motion = {{1, {0, 0, 0}, aboutZ(0)}, {1, {1, 0, 0}, aboutZ(0)}};
  EXPECT_EQ(*obstacleProblem(o),
            "cube.obj: keyframe 1's time must be finite and later than the one before");
  o = unitCube();
  o.placement.rotation.coeffs() *= 2;
  EXPECT_EQ(*obstacleProblem(o), "cube.obj: the rotation must be a unit quaternion");
  o.shape.reset();
  EXPECT_EQ(*obstacleProblem(o), "cube.obj: no surface");
}

// The floor as an obstacle: the exact distance to its plane along the up
// axis, found above it within the radius only and below it at any depth.
TEST(Obstacle, TheFloorIsTheHalfSpaceBelowItsPlane) {
  const Obstacle floor = floorObstacle({UpAxis::Z, 0.5}, 0.6, 0);
  EXPECT_EQ(floor.name, "the floor");
  EXPECT_EQ(floor.staticFriction, 0.6);
  EXPECT_EQ(floor.kineticFriction, 0.6);
  EXPECT_FALSE(obstacleProblem(floor).has_value());
  const auto above = closestPointOf(floor, 0, {1, 2, 0.8}, 0.5);
  ASSERT_TRUE(above.has_value());
  EXPECT_NEAR(above->distance, 0.3, 1e-15);
  EXPECT_EQ(above->point, Eigen::Vector3d(1, 2, 0.5));
  EXPECT_EQ(above->normal, Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(closestPointOf(floor, 0, {1, 2, 1.1}, 0.5).has_value());  // beyond the radius
  const auto deep = closestPointOf(floor, 0, {1, 2, -9.5}, 0.5);         // 10 below: still found
  ASSERT_TRUE(deep.has_value());
  EXPECT_EQ(deep->distance, -10);
  Obstacle bad = floor;
  bad.floor->height = std::nan("");
  EXPECT_EQ(*obstacleProblem(bad), "the floor: the height must be finite, got nan");
}

}  // namespace
}  // namespace tetskin
