// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/meshing/TargetSizing.h"

namespace tetskin {
namespace {

// n = n0 + k V / a solved for a: 606 elements from 6 with k = 2 in a volume
// of 3 need a = 2 * 3 / 600.
TEST(TargetSizing, FirstBoundSolvesTheModelForTheTarget) {
  EXPECT_DOUBLE_EQ(firstVolumeBound(3.0, 6, 606, 2.0), 0.01);
  EXPECT_DOUBLE_EQ(firstVolumeBound(1.0, 0, 1000, kFirstTetGenSizingFactor),
                   kFirstTetGenSizingFactor / 1000);
  EXPECT_THROW(firstVolumeBound(0.0, 6, 606, 2.0), Error);    // no volume
  EXPECT_THROW(firstVolumeBound(-1.0, 6, 606, 2.0), Error);   // inside out
  EXPECT_THROW(firstVolumeBound(3.0, 606, 606, 2.0), Error);  // the surface needs the target
  EXPECT_THROW(firstVolumeBound(3.0, 6, 606, 0.0), Error);    // no factor
  EXPECT_THROW(firstVolumeBound(3.0, 6, std::nan(""), 2.0), Error);
}

// The next bound measures k on the last mesh: 1206 elements (1200 added)
// under a = 0.01 in V = 3 give k = 4, so 606 elements need a = 4 * 3 / 600.
TEST(TargetSizing, NextBoundMeasuresTheFactorOnTheLastMesh) {
  EXPECT_DOUBLE_EQ(nextVolumeBound(3.0, 6, 606, 0.01, 1206), 0.02);
  // A mesh on target gives its own bound back.
  EXPECT_DOUBLE_EQ(nextVolumeBound(3.0, 6, 606, 0.01, 606), 0.01);
}

// One odd mesh moves the bound by at most kMaxBoundStep either way; a bound
// that added nothing takes the smallest step finer.
TEST(TargetSizing, NextBoundStaysWithinAStepOfTheLast) {
  EXPECT_DOUBLE_EQ(nextVolumeBound(3.0, 6, 606, 0.01, 6), 0.01 / kMaxBoundStep);
  EXPECT_DOUBLE_EQ(nextVolumeBound(3.0, 6, 606, 0.01, 7), 0.01 / kMaxBoundStep);
  EXPECT_DOUBLE_EQ(nextVolumeBound(3.0, 6, 606, 0.01, 1e9), 0.01 * kMaxBoundStep);
}

// maxh for a volume bound: the edge of the regular tetrahedron of that volume.
TEST(TargetSizing, EdgeOfTheRegularTetrahedronOfTheBound) {
  const double edge = 0.3;
  const double regularVolume = edge * edge * edge / (6 * std::sqrt(2.0));
  EXPECT_NEAR(edgeForVolumeBound(regularVolume), edge, 1e-12);
}

TEST(TargetSizing, CloseMeansWithinTheTolerance) {
  EXPECT_TRUE(closeToTarget(1000, 1000));
  EXPECT_TRUE(closeToTarget(1000 * (1 + kSizingTolerance), 1000));
  EXPECT_TRUE(closeToTarget(1000 * (1 - kSizingTolerance), 1000));
  EXPECT_FALSE(closeToTarget(1000 * (1 + 2 * kSizingTolerance), 1000));
  EXPECT_FALSE(closeToTarget(1000 * (1 - 2 * kSizingTolerance), 1000));
}

}  // namespace
}  // namespace tetskin
