// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "tetskin/core/Error.h"
#include "tetskin/meshing/LevelSelection.h"

namespace tetskin {
namespace {

TEST(LevelSelection, TargetsFollowTheGeometricFormula) {
  const auto t = levelTargets(600, 12000, 3);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[0], 600);
  EXPECT_NEAR(t[1], 600 * std::sqrt(20.0), 1e-9);  // 2683.28
  EXPECT_DOUBLE_EQ(t[2], 12000);
  const auto five = levelTargets(100, 1600, 5);
  EXPECT_NEAR(five[1], 200, 1e-9);
  EXPECT_NEAR(five[2], 400, 1e-9);
  EXPECT_NEAR(five[3], 800, 1e-9);
  EXPECT_EQ(levelTargets(10, 50, 1), std::vector<double>{50});
  EXPECT_THROW(levelTargets(100, 50, 3), Error);
  EXPECT_THROW(levelTargets(100, 500, 0), Error);
}

TEST(LevelSelection, ClosestCountWinsAndTiesGoToTheEarlierCandidate) {
  // Search order: finest input's best quality first.
  const std::vector<Index> counts = {12500, 9000, 2700, 2666, 610, 590};
  const auto chosen = selectLevels(counts, levelTargets(600, 12000, 3));
  EXPECT_EQ(chosen, (std::vector<int>{4, 2, 0}));
  // 590 and 610 are equally close to 600: the first in search order wins.
  EXPECT_EQ(selectLevels({590, 610}, {600}), std::vector<int>{0});
  EXPECT_EQ(selectLevels({610, 590}, {600}), std::vector<int>{0});
}

TEST(LevelSelection, FailedCandidatesAreNeverChosen) {
  EXPECT_EQ(selectLevels({-1, 5000, -1}, {600, 12000}), (std::vector<int>{1, 1}));
  EXPECT_THROW(selectLevels({-1, -1}, {600}), Error);
  EXPECT_THROW(selectLevels({}, {600}), Error);
}

}  // namespace
}  // namespace tetskin
