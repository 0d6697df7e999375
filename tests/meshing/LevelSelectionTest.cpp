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

TEST(LevelSelection, WarningsNameRepeatedLevelsAndCountsFarFromTheirTargets) {
  const std::vector<double> targets = levelTargets(600, 12000, 3);  // 600, 2683, 12000
  // Every target met within a factor of 2: nothing to say.
  EXPECT_TRUE(selectionWarnings({12500, 2700, 610}, {2, 1, 0}, targets).empty());
  EXPECT_TRUE(selectionWarnings({1200, 2700, 6000}, {0, 1, 2}, targets).empty());
  // One candidate for all three levels (a single input without --decimate).
  EXPECT_EQ(selectionWarnings({22431}, {0, 0, 0}, targets),
            (std::vector<std::string>{"level 0 has 22431 elements, 37x its target of 600",
                                      "levels 0 and 1 are the same candidate (22431 elements)",
                                      "level 1 has 22431 elements, 8.4x its target of 2683",
                                      "levels 1 and 2 are the same candidate (22431 elements)"}));
  // Too few elements; exactly half a target is still within the tolerance.
  EXPECT_EQ(selectionWarnings({290, 700, 5000}, {0, 1, 2}, targets),
            (std::vector<std::string>{"level 0 has 290 elements, 1/2.1 of its target of 600",
                                      "level 1 has 700 elements, 1/3.8 of its target of 2683",
                                      "level 2 has 5000 elements, 1/2.4 of its target of 12000"}));
  EXPECT_TRUE(selectionWarnings({300, 1342, 6000}, {0, 1, 2}, targets).empty());
  EXPECT_EQ(selectionWarnings({100}, {0}, {12000}),
            std::vector<std::string>{"level 0 has 100 elements, 1/120 of its target of 12000"});
}

}  // namespace
}  // namespace tetskin
