// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <limits>

#include "tetskin/core/NumberText.h"

namespace tetskin {
namespace {

TEST(NumberText, RoundOffBesideTheLargestComponentReadsZero) {
  // The GUI's reaction at rest under gravity, as issue #52 saw it.
  EXPECT_EQ(commaSeparatedToScale({-1.23038e-10, 20748.1, 2.85218e-11}), "0,20748.1,0");
  EXPECT_EQ(commaSeparatedToScale({-1.23038e-10, -20748.1, 2.85218e-11}), "0,-20748.1,0");
  EXPECT_EQ(commaSeparatedToScale({0, 0, 0}), "0,0,0");
}

TEST(NumberText, KeepsTheDigitsDownToTheResolutionOfTheScale) {
  EXPECT_EQ(formatToScale(20748.1234, 20748.1234), "20748.1");
  EXPECT_EQ(formatToScale(3.14159, 20748.1), "3.1");      // resolution 0.1
  EXPECT_EQ(formatToScale(0.04, 20748.1), "0");           // below half of it
  EXPECT_EQ(formatToScale(0.06, 20748.1), "0.1");         // rounded to it
  EXPECT_EQ(formatToScale(1.5e-3, 2.0e-3, 3), "0.0015");  // both small: digits kept
  EXPECT_EQ(formatToScale(5.92e-23, 1e-10, 4), "0");      // below the floor
  EXPECT_EQ(formatToScale(5.92e-23, 0, 3), "5.92e-23");   // its own scale
  EXPECT_EQ(formatToScale(-2.5e6, 2.5e6, 3), "-2.5e+06");
  EXPECT_EQ(formatToScale(123456789, 123456789, 4), "1.235e+08");
}

TEST(NumberText, NonFiniteValuesAndScalesDoNotHideAValue) {
  EXPECT_EQ(formatToScale(std::numeric_limits<double>::infinity(), 1), "inf");
  EXPECT_EQ(formatToScale(std::numeric_limits<double>::quiet_NaN(), 1), "nan");
  EXPECT_EQ(formatToScale(7.25, std::numeric_limits<double>::quiet_NaN(), 3), "7.25");
  EXPECT_EQ(formatToScale(7.25, -1, 3), "7.25");
}

}  // namespace
}  // namespace tetskin
