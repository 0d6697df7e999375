// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "tetskin/spatial/TriangleIntersection.h"

namespace tetskin {
namespace {

using V = Eigen::Vector3d;

bool intersect(V p0, V p1, V p2, std::array<int, 3> pi, V q0, V q1, V q2, std::array<int, 3> qi) {
  const V p[3] = {p0, p1, p2}, q[3] = {q0, q1, q2};
  const int pid[3] = {pi[0], pi[1], pi[2]}, qid[3] = {qi[0], qi[1], qi[2]};
  const bool a = trianglesIntersect(p, pid, q, qid);
  EXPECT_EQ(a, trianglesIntersect(q, qid, p, pid)) << "the test must be symmetric";
  return a;
}

TEST(TriangleIntersection, DisjointTriangles) {
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 1}, {1, 0, 1},
                         {0, 1, 1}, {3, 4, 5}));
  // Piercing: an edge of q goes through p's interior.
  EXPECT_TRUE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0.2, 0.2, -1}, {0.2, 0.2, 1},
                        {0.5, 1, 0.5}, {3, 4, 5}));
  // Coplanar overlap.
  EXPECT_TRUE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0.1, 0.1, 0}, {2, 0.1, 0},
                        {0.1, 2, 0}, {3, 4, 5}));
  // Coplanar, apart.
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {2, 2, 0}, {3, 2, 0},
                         {2, 3, 0}, {3, 4, 5}));
}

TEST(TriangleIntersection, SharedEdgeIsProperUnlessFolded) {
  // Two faces of a box meeting at the edge (0,1).
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {1, 0, 0},
                         {0, 0, 1}, {0, 1, 3}));
  // Flat neighbours (opposite sides of the shared edge).
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {1, 0, 0},
                         {0, -1, 0}, {0, 1, 3}));
  // Folded onto each other (same side, coplanar).
  EXPECT_TRUE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {1, 0, 0},
                        {0.5, 0.5, 0}, {0, 1, 3}));
}

TEST(TriangleIntersection, SharedVertex) {
  // Fan around a vertex: proper.
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {0, 1, 0},
                         {-1, 0, 0}, {0, 2, 3}));
  EXPECT_FALSE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {-1, 0, 1},
                         {-1, -1, 1}, {0, 3, 4}));
  // Second triangle cuts through the first beyond the shared vertex.
  EXPECT_TRUE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {1, 1, -1},
                        {1, 1, 1}, {0, 3, 4}));
  // Coplanar, overlapping wedges.
  EXPECT_TRUE(intersect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 2}, {0, 0, 0}, {1, 0.2, 0},
                        {0.2, 1, 0}, {0, 3, 4}));
}

// A flat square split into a 3x3 grid of triangle pairs, turned off the
// axes: the corners are coplanar only up to rounding, where a plain
// floating-point sign took neighbours for intersecting ones (a CAD model's
// flat faces). None intersect.
TEST(TriangleIntersection, NeighboursOnATurnedFlatFaceDoNotIntersect) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.61, V::UnitX()) * Eigen::AngleAxisd(0.37, V::UnitZ()))
          .toRotationMatrix();
  constexpr int n = 3;
  auto corner = [&](int i, int j) { return V(turn * V(i / double(n), j / double(n), 1.0)); };
  auto id = [](int i, int j) { return i * (n + 1) + j; };
  std::vector<std::array<V, 3>> corners;
  std::vector<std::array<int, 3>> ids;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      corners.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
      ids.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      corners.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
      ids.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (std::size_t a = 0; a < corners.size(); ++a)
    for (std::size_t b = a + 1; b < corners.size(); ++b)
      EXPECT_FALSE(intersect(corners[a][0], corners[a][1], corners[a][2], ids[a], corners[b][0],
                             corners[b][1], corners[b][2], ids[b]))
          << a << " " << b;
}

}  // namespace
}  // namespace tetskin
