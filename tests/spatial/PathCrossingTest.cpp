// SPDX-License-Identifier: AGPL-3.0-or-later
// crossingTime: known times of a point passing through a still triangle
// and of a triangle sweeping over a still point; no crossing beside the
// triangle, from its inner side, or short of it.
#include <gtest/gtest.h>

#include "tetskin/spatial/PathCrossing.h"

namespace tetskin {
namespace {

// In the plane z = 0, wound counter-clockwise seen from +z: its outside.
const std::array<Eigen::Vector3d, 3> kTriangle{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                               Eigen::Vector3d(0, 1, 0)};

std::array<Eigen::Vector3d, 3> shifted(const Eigen::Vector3d& by) {
  return {kTriangle[0] + by, kTriangle[1] + by, kTriangle[2] + by};
}

TEST(PathCrossing, APointThroughAStillTriangleCrossesWhereItMeetsThePlane) {
  // From z = 0.3 to z = -0.1 over (0.2, 0.2): through the plane at 3/4.
  EXPECT_NEAR(crossingTime({0.2, 0.2, 0.3}, {0.2, 0.2, -0.1}, kTriangle, kTriangle), 0.75, 1e-15);
  // Slanted, into the triangle's edge x + y = 1 at the crossing.
  EXPECT_NEAR(crossingTime({0.0, 0.0, 0.5}, {1.0, 1.0, -0.5}, kTriangle, kTriangle), 0.5, 1e-15);
}

TEST(PathCrossing, ATriangleSweepingOverAStillPointCrossesIt) {
  // The triangle rises from z = -0.5 to z = 0.5 through the point at z = 0.1.
  EXPECT_NEAR(
      crossingTime({0.3, 0.3, 0.1}, {0.3, 0.3, 0.1}, shifted({0, 0, -0.5}), shifted({0, 0, 0.5})),
      0.6, 1e-15);
}

TEST(PathCrossing, NoCrossingBesideFromInsideOrShortOfIt) {
  EXPECT_EQ(crossingTime({0.8, 0.8, 0.3}, {0.8, 0.8, -0.3}, kTriangle, kTriangle), 2);  // beside
  EXPECT_EQ(crossingTime({0.2, 0.2, -0.3}, {0.2, 0.2, 0.3}, kTriangle, kTriangle),
            2);                                                                        // inner side
  EXPECT_EQ(crossingTime({0.2, 0.2, 0.3}, {0.2, 0.2, 0.1}, kTriangle, kTriangle), 2);  // short
  // Both moving the same way: the point stays above.
  EXPECT_EQ(crossingTime({0.2, 0.2, 0.3}, {0.2, 0.2, -0.2}, kTriangle, shifted({0, 0, -1})), 2);
  // A degenerate triangle.
  const std::array<Eigen::Vector3d, 3> line{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                            Eigen::Vector3d(2, 0, 0)};
  EXPECT_EQ(crossingTime({0.5, 0.0, 0.3}, {0.5, 0.0, -0.3}, line, line), 2);
}

}  // namespace
}  // namespace tetskin
