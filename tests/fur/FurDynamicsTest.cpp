// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "tetskin/fur/FurDynamics.h"

namespace tetskin {
namespace {

TEST(FurDynamics, AtRestTheShellsStandAlongTheNormal) {
  const Eigen::Vector3d n(0, 0, 1);
  const Eigen::Vector3d o = furShellOffset(n, Eigen::Vector3d::Zero(), 0.5, 2.0, {});
  EXPECT_TRUE(o.isApprox(Eigen::Vector3d(0, 0, 1)));
}

TEST(FurDynamics, ShellsTrailTheMotionMoreWithHeight) {
  const Eigen::Vector3d n(0, 0, 1), v(1, 0, 0);
  FurDynamicsOptions d;
  d.drag = 0.01;
  const double low = furShellOffset(n, v, 0.25, 1.0, d).x();
  const double high = furShellOffset(n, v, 1.0, 1.0, d).x();
  EXPECT_LT(low, 0);  // against the velocity
  EXPECT_LT(high, low);
  EXPECT_NEAR(high, -0.01, 1e-15);
  EXPECT_NEAR(low, -0.01 / 16, 1e-15);
}

TEST(FurDynamics, TheShiftIsBoundedAndFurNeverSinksIntoTheSkin) {
  std::mt19937 random(7);
  std::normal_distribution<double> gauss;
  FurDynamicsOptions d;
  d.drag = 5;  // violent
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d n =
        Eigen::Vector3d(gauss(random), gauss(random), gauss(random)).normalized();
    const Eigen::Vector3d v = 100 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
    const double h = (i % 10 + 1) / 10.0, length = 0.3;
    const Eigen::Vector3d o = furShellOffset(n, v, h, length, d);
    const Eigen::Vector3d shift = o - h * length * n;
    EXPECT_GE(o.dot(n), d.minLift * h * length - 1e-12);
    // The lift correction may add at most what keeps the point above minLift.
    EXPECT_LE(shift.norm(), (d.maxBend + 1.0) * h * length + 1e-12);
    const Eigen::Vector3d tangential = shift - shift.dot(n) * n;
    EXPECT_LE(tangential.norm(), d.maxBend * h * length + 1e-12);
  }
}

TEST(FurDynamics, VelocitiesFromTwoFrames) {
  Points3 a(2, 3), b(2, 3), v;
  a << 0, 0, 0, 1, 1, 1;
  b << 0.5, 0, 0, 1, 1, 2;
  furVelocities(a, b, 0.5, v);
  EXPECT_TRUE(v.row(0).isApprox(Eigen::RowVector3d(1, 0, 0)));
  EXPECT_TRUE(v.row(1).isApprox(Eigen::RowVector3d(0, 0, 2)));
  furVelocities(Points3(), b, 0.5, v);  // first frame
  EXPECT_EQ(v.rows(), 2);
  EXPECT_EQ(v.norm(), 0.0);
}

}  // namespace
}  // namespace tetskin
