// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "ExpectError.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {
namespace {

// Two positive tetrahedra sharing the face (1, 2, 3), plus an unused node 5.
TetMesh twoTets() {
  TetMesh m;
  m.nodes.resize(6, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 9, 9, 9;
  m.elements.resize(2, 4);
  m.elements << 0, 1, 2, 3, 4, 1, 3, 2;
  return m;
}

TEST(TetMesh, ElementVolumesArePositive) {
  const TetMesh m = twoTets();
  EXPECT_NEAR(elementVolume(m, 0), 1.0 / 6.0, 1e-15);
  EXPECT_GT(elementVolume(m, 1), 0.0);
  EXPECT_NO_THROW(validateTetMesh(m, "m"));
  EXPECT_DOUBLE_EQ(meshVolume(m), elementVolume(m, 0) + elementVolume(m, 1));
  TetMesh turned = m;  // one element inverted: its volume counts against
  std::swap(turned.elements(1, 0), turned.elements(1, 1));
  EXPECT_DOUBLE_EQ(meshVolume(turned), elementVolume(m, 0) - elementVolume(m, 1));
}

TEST(TetMesh, InvertedElementIsReported) {
  TetMesh m = twoTets();
  std::swap(m.elements(1, 0), m.elements(1, 1));
  try {
    validateTetMesh(m, "m.ele");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("element 1 has non-positive volume"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(validateTetMesh(m, "m.ele", /*requirePositiveVolume=*/false));
}

// A mesh made with the other orientation convention turns positive; a
// right one is left as it is.
TEST(TetMesh, InvertedElementsAreTurned) {
  TetMesh m = twoTets();
  const TetMesh right = m;
  EXPECT_EQ(orientElementsPositively(m), 0);
  EXPECT_EQ(m.elements, right.elements);
  std::swap(m.elements(1, 0), m.elements(1, 1));
  EXPECT_EQ(orientElementsPositively(m), 1);
  EXPECT_NO_THROW(validateTetMesh(m, "m"));
  EXPECT_NEAR(elementVolume(m, 1), elementVolume(right, 1), 1e-15);
  EXPECT_EQ(m.elements.row(0), right.elements.row(0));
}

TEST(TetMesh, NodeIndexOutOfRangeIsReported) {
  TetMesh m = twoTets();
  m.elements(0, 3) = 6;
  EXPECT_THROW(validateTetMesh(m, "m", false), Error);
  m.elements(0, 3) = -1;
  EXPECT_THROW(validateTetMesh(m, "m", false), Error);
}

TEST(TetMesh, UnreferencedNodesAreFoundAndRemoved) {
  TetMesh m = twoTets();
  EXPECT_EQ(unreferencedNodes(m), std::vector<Index>{5});
  // Make node 0 unused too: the first element now uses node 4 instead.
  m.elements.row(0) << 4, 1, 2, 3;
  std::swap(m.elements(0, 1), m.elements(0, 2));  // keep it positive: (4,2,1,3)
  EXPECT_EQ(unreferencedNodes(m), (std::vector<Index>{0, 5}));
  EXPECT_EQ(removeUnreferencedNodes(m), 2);
  EXPECT_EQ(m.nodeCount(), 4);
  EXPECT_TRUE(unreferencedNodes(m).empty());
  // Node 4 (1,1,1) is now node 3; node 1 (1,0,0) is now node 0.
  EXPECT_EQ(m.nodes.row(3), Eigen::RowVector3d(1, 1, 1));
  EXPECT_EQ(m.elements.row(1), Eigen::RowVector4i(3, 0, 2, 1));
  EXPECT_NO_THROW(validateTetMesh(m, "m"));
}

TEST(TetMesh, LevelsRoundTripThroughAppendAndExtract) {
  MultiLevelTetMesh all;
  TetMesh coarse = twoTets();
  removeUnreferencedNodes(coarse);
  TetMesh fine = coarse;
  fine.nodes *= 2.0;
  appendLevel(all, coarse);
  appendLevel(all, fine);
  ASSERT_EQ(all.levelCount(), 2);
  EXPECT_EQ(all.levels[1], (LevelRange{5, 5, 2, 2}));
  EXPECT_EQ(all.elements(2, 0), coarse.elements(0, 0) + 5);
  EXPECT_NO_THROW(validateLevels(all, "d"));
  const TetMesh back = extractLevel(all, 1);
  EXPECT_EQ(back.nodes, fine.nodes);
  EXPECT_EQ(back.elements, fine.elements);
  EXPECT_THROW(extractLevel(all, 2), Error);
}

TEST(TetMesh, LevelsMustNotReferToOtherLevels) {
  MultiLevelTetMesh all;
  TetMesh a = twoTets();
  removeUnreferencedNodes(a);
  appendLevel(all, a);
  appendLevel(all, a);
  all.elements(3, 0) = 0;  // level 1 element pointing at a level-0 node
  EXPECT_THROW(validateLevels(all, "d"), Error);
}

TEST(TetMesh, LevelsMustCoverTheArraysContiguously) {
  MultiLevelTetMesh all;
  TetMesh a = twoTets();
  removeUnreferencedNodes(a);
  appendLevel(all, a);
  appendLevel(all, a);
  auto message = [&] { return test::errorText([&] { validateLevels(all, "d.json"); }); };
  all.levels[1].firstNode += 1;
  EXPECT_EQ(message(),
            "d.json: level 1 starts at node 6, element 2, but level 0 ends before node 5, element "
            "2 (levels must be contiguous, coarsest first)");
  all.levels[1].firstNode -= 1;
  std::swap(all.levels[0], all.levels[1]);  // finest first
  EXPECT_EQ(message(),
            "d.json: level 0 starts at node 5, element 2, but the first level must start at node "
            "0, element 0 (levels must be contiguous, coarsest first)");
  std::swap(all.levels[0], all.levels[1]);
  all.levels.pop_back();
  EXPECT_THROW(validateLevels(all, "d"), Error);  // level 1's rows are not covered
}

}  // namespace
}  // namespace tetskin
