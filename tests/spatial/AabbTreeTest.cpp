// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <span>

#include "tetskin/spatial/AabbTree.h"

namespace tetskin {
namespace {

std::vector<Aabb> randomBoxes(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-10, 10), size(0, 0.8);
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  for (Aabb& b : boxes) {
    const Eigen::Vector3d p(pos(rng), pos(rng), pos(rng));
    b.extend(p);
    b.extend(p + Eigen::Vector3d(size(rng), size(rng), size(rng)));
  }
  return boxes;
}

TEST(AabbTree, OverlapQueryEqualsBruteForce) {
  std::mt19937 rng(1);
  const auto boxes = randomBoxes(3000, rng);
  const AabbTree tree(boxes);
  EXPECT_EQ(tree.primitiveCount(), boxes.size());
  for (const Aabb& query : randomBoxes(200, rng)) {
    const Aabb q = query.inflated(0.5);
    std::vector<int> found, expected;
    tree.forEachOverlap(q, [&](int id) { found.push_back(id); });
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (boxes[i].overlaps(q)) expected.push_back(static_cast<int>(i));
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
  }
}

TEST(AabbTree, NearestBoxEqualsBruteForce) {
  std::mt19937 rng(2);
  const auto boxes = randomBoxes(2000, rng);
  const AabbTree tree(boxes);
  std::uniform_real_distribution<double> pos(-15, 15);
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p(pos(rng), pos(rng), pos(rng));
    double best = std::numeric_limits<double>::infinity();
    int bestId = -1;
    tree.forEachNear(p, best, [&](int id, double& radius2) {
      const double d = boxes[static_cast<std::size_t>(id)].squaredDistance(p);
      if (d < radius2 || (d == radius2 && id < bestId)) {
        radius2 = d;
        bestId = id;
      }
    });
    double expected = std::numeric_limits<double>::infinity();
    for (const Aabb& b : boxes) expected = std::min(expected, b.squaredDistance(p));
    EXPECT_EQ(best, expected);
  }
}

// anyOverlap says whether forEachOverlap would find anything, and
// forEachLeafNear reports every primitive of this tree whose box, grown by
// the margin, overlaps a box of the other (the leaves it reports may hold
// more: it is conservative, never short), each once; with the trees far
// apart it reports nothing.
TEST(AabbTree, LeavesNearAnotherTreeHoldEveryPrimitiveNearIt) {
  std::mt19937 rng(3);
  const auto mine = randomBoxes(1500, rng);
  std::vector<Aabb> theirs = randomBoxes(300, rng);
  for (Aabb& b : theirs) b = {b.min * 0.3, b.max * 0.3};  // a smaller cluster in the middle
  const AabbTree tree(mine), other(theirs);
  for (const Aabb& query : randomBoxes(100, rng)) {
    bool expected = false;
    for (const Aabb& b : theirs) expected = expected || b.overlaps(query);
    EXPECT_EQ(other.anyOverlap(query), expected);
  }
  const double margin = 0.4;
  std::vector<int> reported;
  tree.forEachLeafNear(other, margin, [&](std::span<const int> ids) {
    reported.insert(reported.end(), ids.begin(), ids.end());
  });
  std::sort(reported.begin(), reported.end());
  EXPECT_EQ(std::adjacent_find(reported.begin(), reported.end()), reported.end());  // each once
  int near = 0;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    bool isNear = false;
    for (const Aabb& b : theirs) isNear = isNear || mine[i].inflated(margin).overlaps(b);
    if (!isNear) continue;
    ++near;
    EXPECT_TRUE(std::binary_search(reported.begin(), reported.end(), static_cast<int>(i))) << i;
  }
  EXPECT_GT(near, 0);
  EXPECT_LT(reported.size(), mine.size() / 2);  // it does leave the far ones out
  std::vector<Aabb> far = theirs;
  for (Aabb& b : far) b = {b.min.array() + 100, b.max.array() + 100};
  int visits = 0;
  tree.forEachLeafNear(AabbTree(far), margin, [&](std::span<const int>) { ++visits; });
  EXPECT_EQ(visits, 0);
}

TEST(AabbTree, EmptyTreeVisitsNothing) {
  const AabbTree tree;
  int visits = 0;
  tree.forEachOverlap(Aabb{}.inflated(1e9), [&](int) { ++visits; });
  double r2 = 1e300;
  tree.forEachNear(Eigen::Vector3d::Zero(), r2, [&](int, double&) { ++visits; });
  EXPECT_FALSE(tree.anyOverlap(Aabb{}.inflated(1e9)));
  tree.forEachLeafNear(tree, 1e9, [&](std::span<const int>) { ++visits; });
  EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace tetskin
