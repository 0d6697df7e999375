// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "tetskin/core/UpAxis.h"

namespace tetskin {
namespace {

TEST(UpAxis, NamesReadBackAndOthersAreRefused) {
  for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    EXPECT_EQ(parseName<UpAxis>(toString(up)), up);
    EXPECT_EQ(upVector(up)[axisIndex(up)], 1.0);
    EXPECT_EQ(upVector(up).norm(), 1.0);
  }
  EXPECT_EQ(parseName<UpAxis>("Z"), UpAxis::Z);
  for (const char* bad : {"", "w", "-z", "zz", "up"}) EXPECT_FALSE(parseName<UpAxis>(bad)) << bad;
}

// fromYUp is a proper rotation taking y to the up axis, so directions given
// for y-up (camera presets, the sideways push) keep their handedness.
TEST(UpAxis, FromYUpIsARotationTakingYToTheAxis) {
  for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z}) {
    const Eigen::Matrix3d r = fromYUp(up);
    EXPECT_TRUE((r * r.transpose()).isIdentity(1e-15)) << toString(up);
    EXPECT_DOUBLE_EQ(r.determinant(), 1.0) << toString(up);
    EXPECT_TRUE((r * Eigen::Vector3d::UnitY()).isApprox(upVector(up))) << toString(up);
    // A horizontal direction stays horizontal.
    EXPECT_EQ((r * Eigen::Vector3d::UnitX())[axisIndex(up)], 0.0) << toString(up);
    EXPECT_EQ((r * Eigen::Vector3d::UnitZ())[axisIndex(up)], 0.0) << toString(up);
  }
  EXPECT_TRUE(fromYUp(UpAxis::Y).isIdentity());
}

}  // namespace
}  // namespace tetskin
