// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/io/LoadCurveFile.h"

namespace tetskin {
namespace {

TEST(LoadCurveFile, PointsInOrderWithComments) {
  const test::ScratchDir dir;
  const auto file = dir.write("ramp.txt",
                              "\xEF\xBB\xBF# ramp up in half a second, hold, let go\n"
                              "0 0\n"
                              "\n"
                              "0.5\t1   # full load\n"
                              "2 1\r\n"
                              "2.01 0\n");
  const LoadCurve curve = readLoadCurve(file);
  ASSERT_EQ(curve.points().size(), 4u);
  EXPECT_EQ(curve.points()[1].time, 0.5);
  EXPECT_EQ(curve.points()[3].factor, 0);
  EXPECT_DOUBLE_EQ(curve.factorAt(0.25), 0.5);
  EXPECT_EQ(curve.factorAt(3), 0);
}

TEST(LoadCurveFile, RepeatOnTheLastLineRepeatsTheCurve) {
  const test::ScratchDir dir;
  const LoadCurve pulses = readLoadCurve(dir.write("pulses.txt",
                                                   "# a pulse every second\n"
                                                   "0 0\n0.1 1\n0.2 0\n1 0\n"
                                                   "repeat  # forever\n"));
  EXPECT_EQ(pulses.after(), LoadCurve::After::Repeat);
  EXPECT_NEAR(pulses.factorAt(5.05), 0.5, 1e-12);
  EXPECT_EQ(readLoadCurve(dir.write("held.txt", "0 0\n0.1 1\n")).after(), LoadCurve::After::Hold);
}

TEST(LoadCurveFile, BadPointsNameTheFileAndLine) {
  const test::ScratchDir dir;
  auto expectError = [&](const std::string& content, long line, const std::string& what) {
    const auto file = dir.write("bad_curve.txt", content);
    test::expectErrorAt([&] { readLoadCurve(file); }, file.string(), line, what);
  };
  expectError("0 0\n1\n", 2, "load curve point (TIME FACTOR): expected 2 values, found 1");
  expectError("0 0 1\n", 1, "expected 2 values, found 3");
  expectError("# t f\n0 0\n1 1\n1 2\n", 4, "the times must increase, but 1 s follows 1 s");
  expectError("0 0\n-1 1\n", 2, "the times must increase, but -1 s follows 0 s");
  expectError("x 1\n", 1, "time 'x'");
  expectError("0 nan\n", 1, "factor 'nan'");
  expectError("0 1e999\n", 1, "factor '1e999'");
  expectError("# none\n", 0, "no points in the file");
  expectError("0 0\nrepeat\n", 2, "'repeat' needs two points or more before it");
  expectError("0 0\n1 1\nrepeat\n2 0\n", 4, "nothing may follow 'repeat'");
  expectError("0 0\n1 1\nrepeat\nrepeat\n", 4, "nothing may follow 'repeat'");
  expectError("0 0\nrepeat 2\n", 2, "time 'repeat' is not a number");
  test::expectErrorAt([&] { readLoadCurve(dir / "absent.txt"); }, (dir / "absent.txt").string(), 0,
                      "cannot open");
}

}  // namespace
}  // namespace tetskin
