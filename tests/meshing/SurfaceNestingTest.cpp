// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <numeric>

#include "Shapes.h"
#include "tetskin/meshing/SurfaceNesting.h"

namespace tetskin {
namespace {

SurfaceMesh inverted(SurfaceMesh mesh) {
  mesh.triangles.col(1).swap(mesh.triangles.col(2));
  return mesh;
}

SurfaceMesh cube(double half) {
  return test::box(Eigen::Vector3d::Constant(-half), Eigen::Vector3d::Constant(half));
}

std::vector<int> allTriangles(const SurfaceMesh& mesh) {
  std::vector<int> all(static_cast<std::size_t>(mesh.triangleCount()));
  std::iota(all.begin(), all.end(), 0);
  return all;
}

TEST(SurfaceNesting, WindingNumberIsOneInsideZeroOutsideMinusOneWoundInward) {
  const SurfaceMesh box = cube(1);
  const std::vector<int> all = allTriangles(box);
  EXPECT_NEAR(windingNumber(box, all, {0.2, -0.3, 0.9}), 1.0, 1e-12);
  EXPECT_NEAR(windingNumber(box, all, {1.5, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(windingNumber(box, all, {30, -20, 10}), 0.0, 1e-12);
  EXPECT_NEAR(windingNumber(inverted(box), all, {0.2, -0.3, 0.9}), -1.0, 1e-12);
}

TEST(SurfaceNesting, PartsAreTheTrianglesJoinedAcrossSharedEdges) {
  const SurfaceMesh two = test::merge(cube(1), test::box({3, 0, 0}, {4, 1, 1}));
  const SurfaceParts parts = surfaceParts(two);
  ASSERT_EQ(parts.triangles.size(), 2u);
  EXPECT_EQ(parts.triangles[0].size(), 12u);
  EXPECT_EQ(parts.triangles[1].front(), 12);  // in order of their first triangle
  for (const auto& part : parts.triangles) {
    EXPECT_EQ(parts.reachedFrom[static_cast<std::size_t>(part.front())], -1);
    // Each later triangle was reached from one listed before it.
    for (std::size_t k = 1; k < part.size(); ++k) {
      const int from = parts.reachedFrom[static_cast<std::size_t>(part[k])];
      EXPECT_NE(std::find(part.begin(), part.begin() + static_cast<long>(k), from),
                part.begin() + static_cast<long>(k));
    }
  }
  EXPECT_NEAR(partVolume(two, parts.triangles[0]), 8.0, 1e-12);
  EXPECT_NEAR(partVolume(inverted(two), parts.triangles[1]), -1.0, 1e-12);
}

TEST(SurfaceNesting, APartInsideAnotherIsEnclosedByIt) {
  const SurfaceMesh nested = test::merge(test::merge(cube(3), cube(2)), cube(1));
  const auto parts = surfaceParts(nested).triangles;
  ASSERT_EQ(parts.size(), 3u);
  const auto enclosing = enclosingParts(nested, parts);
  EXPECT_TRUE(enclosing[0].empty());
  EXPECT_EQ(enclosing[1], std::vector<int>{0});
  EXPECT_EQ(enclosing[2], (std::vector<int>{0, 1}));
  const SurfaceMesh apart = test::merge(cube(1), test::box({3, 0, 0}, {4, 1, 1}));
  for (const auto& e : enclosingParts(apart, surfaceParts(apart).triangles)) EXPECT_TRUE(e.empty());
  // Stacked face to face: the upper box's probe lies on the lower's top.
  const SurfaceMesh stacked =
      test::merge(test::box({-2, -2, -2}, {2, 2, 2}), test::box({-2, 2, -2}, {2, 3, 2}));
  for (const auto& e : enclosingParts(stacked, surfaceParts(stacked).triangles))
    EXPECT_TRUE(e.empty());
}

TEST(SurfaceNesting, AnInnerPartWoundTheOtherWayBoundsACavity) {
  auto cavities = [](const SurfaceMesh& mesh) {
    const auto parts = surfaceParts(mesh).triangles;
    return cavityParts(mesh, parts, enclosingParts(mesh, parts));
  };
  // A hollow ball as STL has it: the inner wall faces into the cavity.
  EXPECT_EQ(cavities(test::merge(cube(2), inverted(cube(1)))), (std::vector<char>{0, 1}));
  // Wound alike, the inner part is solid through (2 inside it).
  EXPECT_EQ(cavities(test::merge(cube(2), cube(1))), (std::vector<char>{0, 0}));
  // A ball in a hollow ball: inside the ball 1 - 1 + 1 = 1, solid.
  EXPECT_EQ(cavities(test::merge(test::merge(cube(3), inverted(cube(2))), cube(1))),
            (std::vector<char>{0, 1, 0}));
  // Wound inside out throughout, the hollow ball is still hollow.
  EXPECT_EQ(cavities(test::merge(inverted(cube(2)), cube(1))), (std::vector<char>{0, 1}));
}

TEST(SurfaceNesting, EachCavityGetsAPointInsideIt) {
  const SurfaceMesh hollow = test::merge(cube(2), inverted(cube(1)));
  const auto points = cavityPoints(hollow);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_LT(points[0].cwiseAbs().maxCoeff(), 1.0);  // inside the inner cube
  const std::vector<int> all = allTriangles(hollow);
  EXPECT_NEAR(windingNumber(hollow, all, points[0]), 0.0, 1e-9);  // in the void
  EXPECT_TRUE(cavityPoints(cube(2)).empty());
  EXPECT_TRUE(cavityPoints(test::merge(cube(2), cube(1))).empty());
}

}  // namespace
}  // namespace tetskin
