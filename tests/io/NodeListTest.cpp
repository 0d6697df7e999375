// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/io/NodeList.h"

namespace tetskin {
namespace {

TEST(NodeList, NumbersAcrossLinesSortedOnceEachWithComments) {
  const test::ScratchDir dir;
  const auto file = dir.write("held.txt",
                              "\xEF\xBB\xBF# the clamped end\n"
                              "7 3\t3\n"
                              "\n"
                              "+0 9  # last node\n"
                              "3\r\n");
  EXPECT_EQ(readNodeList(file, 10), (std::vector<int>{0, 3, 7, 9}));
}

TEST(NodeList, BadNumbersNameTheFileAndLine) {
  const test::ScratchDir dir;
  auto expectError = [&](const std::string& content, long line, const std::string& what) {
    const auto file = dir.write("bad.txt", content);
    test::expectErrorAt([&] { readNodeList(file, 10); }, file.string(), line, what);
  };
  expectError("1 2\n3 x\n", 2, "node number 'x' is not an integer");
  expectError("1.5\n", 1, "node number '1.5' is not an integer");
  expectError("# ok\n\n10\n", 3,
              "node 10 does not exist (the level has 10 nodes, numbered from 0)");
  expectError("-1\n", 1, "node -1 does not exist");
  expectError("99999999999999999999\n", 1, "'99999999999999999999' is out of range");
  expectError("# nothing here\n", 0, "no node numbers in the file");
  expectError("", 0, "no node numbers in the file");
  test::expectErrorAt([&] { readNodeList(dir / "absent.txt", 10); }, (dir / "absent.txt").string(),
                      0, "cannot open");
}

TEST(NodeList, ForcesPerNodeAddUpWithComments) {
  const test::ScratchDir dir;
  const auto file = dir.write("loads.txt",
                              "# tip load, newtons\n"
                              "4 0 -2.5 0\n"
                              "\n"
                              "1\t1e1 0 +3   # sideways\n"
                              "4 0 -0.5 1\r\n");
  const Points3 forces = readNodeForces(file, 6);
  ASSERT_EQ(forces.rows(), 6);
  EXPECT_EQ(forces.row(4), Eigen::RowVector3d(0, -3, 1));  // given twice: added
  EXPECT_EQ(forces.row(1), Eigen::RowVector3d(10, 0, 3));
  EXPECT_EQ(forces.rowwise().squaredNorm().count(), 2);  // nothing elsewhere
}

TEST(NodeList, BadForcesNameTheFileAndLine) {
  const test::ScratchDir dir;
  auto expectError = [&](const std::string& content, long line, const std::string& what) {
    const auto file = dir.write("bad_loads.txt", content);
    test::expectErrorAt([&] { readNodeForces(file, 10); }, file.string(), line, what);
  };
  expectError("1 0 0 1\n2 0 -1\n", 2, "node force (NODE FX FY FZ): expected 4 values, found 3");
  expectError("1 0 0 1 5\n", 1, "expected 4 values, found 5");
  expectError("10 0 0 1\n", 1, "node 10 does not exist (the level has 10 nodes");
  expectError("x 0 0 1\n", 1, "node number 'x' is not an integer");
  expectError("3 0 nan 1\n", 1, "force 'nan'");
  expectError("3 0 1e999 1\n", 1, "force '1e999'");
  expectError("3 0 1e308 0\n3 0 1e308 0\n", 0, "add up beyond any number");
  expectError("# none\n", 0, "no node forces in the file");
}

}  // namespace
}  // namespace tetskin
