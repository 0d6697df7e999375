// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"
#include "tetskin/core/LoadCurve.h"

namespace tetskin {
namespace {

TEST(LoadCurve, LinearBetweenPointsAndHeldOutsideThem) {
  const LoadCurve ramp({{0.5, 0}, {1.5, 2}, {2, 2}, {3, -1}});
  EXPECT_EQ(ramp.factorAt(-10), 0);  // before the first: its factor
  EXPECT_EQ(ramp.factorAt(0.5), 0);
  EXPECT_DOUBLE_EQ(ramp.factorAt(0.75), 0.5);
  EXPECT_DOUBLE_EQ(ramp.factorAt(1.0), 1.0);
  EXPECT_EQ(ramp.factorAt(1.5), 2);  // at a point: its factor
  EXPECT_EQ(ramp.factorAt(1.75), 2);
  EXPECT_DOUBLE_EQ(ramp.factorAt(2.5), 0.5);
  EXPECT_EQ(ramp.factorAt(3), -1);
  EXPECT_EQ(ramp.factorAt(1e9), -1);  // after the last: its factor
  EXPECT_EQ(describe(ramp), "4 points from 0.5 to 3 s, factors -1 to 2");
}

TEST(LoadCurve, EmptyIsOneAndOnePointIsConstant) {
  const LoadCurve none;
  EXPECT_TRUE(none.empty());
  for (double t : {-1.0, 0.0, 7.5}) EXPECT_EQ(none.factorAt(t), 1);
  EXPECT_EQ(describe(none), "constant 1");
  const LoadCurve half({{2, 0.5}});
  for (double t : {-1.0, 2.0, 7.5}) EXPECT_EQ(half.factorAt(t), 0.5);
  EXPECT_EQ(describe(half), "constant 0.5");
}

// Repeated, the curve's span from its first point to its last is the
// period: one period's points make periodic forcing.
TEST(LoadCurve, RepeatedAfterItsLastPointWithItsSpanAsThePeriod) {
  const LoadCurve saw({{1, 0}, {2, 1}, {3, -1}}, LoadCurve::After::Repeat);
  EXPECT_EQ(saw.factorAt(0), 0);  // before the first: its factor, as held curves
  EXPECT_DOUBLE_EQ(saw.factorAt(1.5), 0.5);
  for (int period : {1, 2, 7})
    for (double t : {1.25, 1.5, 2.0, 2.5})
      EXPECT_NEAR(saw.factorAt(t + 2 * period), saw.factorAt(t), 1e-12) << t;
  EXPECT_NEAR(saw.factorAt(2.999999), -1, 1e-5);
  EXPECT_EQ(saw.factorAt(3), 0);  // the next period's start
  EXPECT_EQ(describe(saw), "3 points from 1 to 3 s, factors -1 to 1, repeated every 2 s");
  const LoadCurve held({{1, 0}, {2, 1}, {3, -1}});
  EXPECT_EQ(held.factorAt(4.5), -1);
  try {
    LoadCurve lone({{0, 1}}, LoadCurve::After::Repeat);
    ADD_FAILURE() << "a repeated one-point curve";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "a repeated load curve needs two points or more (its period is their span)");
  }
}

TEST(LoadCurve, BadPointsAreErrorsNamingThePoint) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto expectError = [](std::vector<LoadCurve::Point> points, const std::string& message) {
    try {
      LoadCurve curve(std::move(points));
      ADD_FAILURE() << "no error for '" << message << "'";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  expectError({{0, 0}, {1, 1}, {1, 2}},
              "load curve point 3: the times must increase, but 1 s follows 1 s");
  expectError({{0, 0}, {-1, 1}},
              "load curve point 2: the times must increase, but -1 s follows 0 s");
  expectError({{nan, 0}}, "load curve point 1: the time must be finite, got nan");
  expectError({{0, 1}, {1, INFINITY}}, "load curve point 2: the factor must be finite, got inf");
  // The check readers use to name a file's line.
  const LoadCurve::Point first{0, 1};
  EXPECT_FALSE(LoadCurve::pointProblem(nullptr, first));
  EXPECT_FALSE(LoadCurve::pointProblem(&first, {1e-9, -3}));
  EXPECT_TRUE(LoadCurve::pointProblem(&first, {0, 3}));
}

}  // namespace
}  // namespace tetskin
