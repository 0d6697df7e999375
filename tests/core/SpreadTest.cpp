// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "tetskin/core/Spread.h"

namespace tetskin {
namespace {

// Nearest rank: of 1..200, the median is 100 (100 values at or below it),
// the 99th percentile 198, the maximum 200; whatever the order given.
TEST(Spread, NearestRankPercentilesOfKnownValues) {
  std::vector<double> sorted(200);
  std::iota(sorted.begin(), sorted.end(), 1.0);
  EXPECT_EQ(percentileOfSorted(sorted, 0.5), 100);
  EXPECT_EQ(percentileOfSorted(sorted, 0.99), 198);
  EXPECT_EQ(percentileOfSorted(sorted, 1.0), 200);
  EXPECT_EQ(percentileOfSorted(sorted, 0.0), 1);
  EXPECT_EQ(percentileOfSorted({}, 0.5), 0);

  std::vector<double> shuffled;
  for (int i = 0; i < 200; ++i)
    shuffled.push_back(sorted[static_cast<std::size_t>((i * 67) % 200)]);
  const Spread s = spreadOf(shuffled);
  EXPECT_EQ(s.median, 100);
  EXPECT_EQ(s.p99, 198);
  EXPECT_EQ(s.max, 200);
}

TEST(Spread, ANanShowsAsTheMaximumAndNoValuesGiveZeros) {
  std::vector<double> values = {3, std::numeric_limits<double>::quiet_NaN(), 1, 2};
  const Spread s = spreadOf(values);
  EXPECT_TRUE(std::isnan(s.max));
  EXPECT_EQ(s.median, 2);
  std::vector<double> none;
  const Spread empty = spreadOf(none);
  EXPECT_EQ(empty.max, 0);
  EXPECT_EQ(empty.median, 0);
}

}  // namespace
}  // namespace tetskin
