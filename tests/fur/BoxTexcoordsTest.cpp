// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/fur/BoxTexcoords.h"

namespace tetskin {
namespace {

// A UV sphere: every cube side is used and seams run through it.
SurfaceMesh sphere(int rings, int segments) {
  SurfaceMesh m;
  m.positions.resize(2 + (rings - 1) * segments, 3);
  m.positions.row(0) << 0, 0, 1;
  m.positions.row(1) << 0, 0, -1;
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
      m.positions.row(2 + (r - 1) * segments + s) << std::sin(theta) * std::cos(phi),
          std::sin(theta) * std::sin(phi), std::cos(theta);
    }
  std::vector<Eigen::Vector3i> t;
  auto id = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    t.emplace_back(0, id(1, s), id(1, s + 1));
    t.emplace_back(1, id(rings - 1, s + 1), id(rings - 1, s));
    for (int r = 1; r + 1 < rings; ++r) {
      t.emplace_back(id(r, s), id(r + 1, s), id(r + 1, s + 1));
      t.emplace_back(id(r, s), id(r + 1, s + 1), id(r, s + 1));
    }
  }
  m.triangles.resize(static_cast<Index>(t.size()), 3);
  for (std::size_t i = 0; i < t.size(); ++i) m.triangles.row(static_cast<Index>(i)) = t[i];
  return m;
}

Eigen::Vector3d faceNormal(const Points3& p, const Triangles& t, Index f) {
  const Eigen::Vector3d a = p.row(t(f, 0));
  return (Eigen::Vector3d(p.row(t(f, 1))) - a).cross(Eigen::Vector3d(p.row(t(f, 2))) - a);
}

TEST(BoxTexcoords, DominantSideIsTheLargestNormalComponent) {
  EXPECT_EQ(dominantSide({1, 0.2, -0.3}), 0);
  EXPECT_EQ(dominantSide({-1, 0.2, -0.3}), 1);
  EXPECT_EQ(dominantSide({0.1, 2, -0.3}), 2);
  EXPECT_EQ(dominantSide({0.1, -2, -0.3}), 3);
  EXPECT_EQ(dominantSide({0.1, 0.2, 0.3}), 4);
  EXPECT_EQ(dominantSide({0.1, 0.2, -0.3}), 5);
}

TEST(BoxTexcoords, CubeCornersSplitIntoThreeCopies) {
  const SurfaceMesh cube = test::box({0, 0, 0}, {2, 2, 2});
  const BoxTexturedSurface b = boxTexcoords(cube.positions, cube.triangles, 1.0);
  EXPECT_EQ(b.splitVertexCount(), 24);  // 8 corners x 3 sides each
  std::set<int> sides(b.sides.begin(), b.sides.end());
  EXPECT_EQ(sides.size(), 6u);
  // Corners of a [0,2] cube with a tile of 1: every coordinate is 0 or +-2,
  // and each side's square spans 2 x 2 tiles undistorted.
  for (Index v = 0; v < b.splitVertexCount(); ++v)
    for (int c = 0; c < 2; ++c)
      EXPECT_TRUE(b.texcoords(v, c) == 0 || std::abs(b.texcoords(v, c)) == 2);
  for (Index t = 0; t < b.triangles.rows(); ++t) {
    const Eigen::Vector2d a = b.texcoords.row(b.triangles(t, 0)),
                          p = b.texcoords.row(b.triangles(t, 1)),
                          q = b.texcoords.row(b.triangles(t, 2));
    const Eigen::Vector2d e1 = p - a, e2 = q - a;
    EXPECT_DOUBLE_EQ(std::abs(e1.x() * e2.y() - e1.y() * e2.x()) / 2, 2.0);  // area 2 = the face's
  }
}

TEST(BoxTexcoords, EveryTriangleTakesTheSideOfItsDominantNormalAxisAndItsPlane) {
  const SurfaceMesh s = sphere(12, 24);
  const double tile = 0.25;
  const BoxTexturedSurface b = boxTexcoords(s.positions, s.triangles, tile);
  const Eigen::RowVector3d corner = s.positions.colwise().minCoeff();
  ASSERT_EQ(b.triangles.rows(), s.triangles.rows());
  for (Index t = 0; t < s.triangles.rows(); ++t) {
    const Eigen::Vector3d n = faceNormal(s.positions, s.triangles, t);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
    const int side = b.sides[static_cast<std::size_t>(t)];
    EXPECT_EQ(side / 2, axis);
    EXPECT_EQ(side % 2 == 1, n[axis] < 0);
    for (int k = 0; k < 3; ++k) {
      const Index copy = b.triangles(t, k);
      EXPECT_EQ(b.source[static_cast<std::size_t>(copy)], s.triangles(t, k));
      // The coordinates are the position's two in-plane components, from
      // the lowest corner, over the tile.
      const Eigen::Vector3d p = s.positions.row(s.triangles(t, k));
      const Eigen::Vector2d uv = b.texcoords.row(copy) * tile;
      for (int c = 0; c < 3; ++c)
        if (c != axis) {
          const double value = p[c] - corner[c];
          EXPECT_TRUE(std::abs(std::abs(uv[0]) - std::abs(value)) < 1e-12 ||
                      std::abs(std::abs(uv[1]) - std::abs(value)) < 1e-12);
        }
    }
  }
}

TEST(BoxTexcoords, AMovedSurfaceKeepsItsCoordinates) {
  // (Before, they were the absolute positions over the tile: 1e6 away, 4e6
  // tiles, which a float holds to about half a tile.)
  SurfaceMesh s = sphere(10, 16);
  // (Turned off the axes: the sphere's faces at 45 degrees between two
  // sides would go either way on a rounding.)
  s.positions =
      s.positions *
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix().transpose();
  SurfaceMesh moved = s;
  moved.positions.rowwise() += Eigen::RowVector3d(1e6, -2e6, 5e5);
  const BoxTexturedSurface here = boxTexcoords(s.positions, s.triangles, 0.25);
  const BoxTexturedSurface there = boxTexcoords(moved.positions, moved.triangles, 0.25);
  ASSERT_EQ(there.texcoords.rows(), here.texcoords.rows());
  EXPECT_LT((there.texcoords - here.texcoords).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(there.texcoords.cwiseAbs().maxCoeff(), 16);  // the sphere spans 8 tiles
}

TEST(BoxTexcoords, SplitCountIsOneCopyPerVertexAndSide) {
  const SurfaceMesh s = sphere(10, 16);
  const BoxTexturedSurface b = boxTexcoords(s.positions, s.triangles, 0.3);
  std::vector<std::set<int>> sidesOf(static_cast<std::size_t>(s.vertexCount()));
  for (Index t = 0; t < s.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      sidesOf[static_cast<std::size_t>(s.triangles(t, k))].insert(
          b.sides[static_cast<std::size_t>(t)]);
  std::size_t expected = 0;
  for (const auto& set : sidesOf) expected += set.size();
  EXPECT_EQ(static_cast<std::size_t>(b.splitVertexCount()), expected);
  EXPECT_GT(b.splitVertexCount(), s.vertexCount());  // there are seams
}

TEST(BoxTexcoords, StitchedNormalsAreEqualAcrossASeamWhereNaiveOnesAreNot) {
  const SurfaceMesh s = sphere(10, 16);
  const BoxTexturedSurface b = boxTexcoords(s.positions, s.triangles, 0.3);
  Points3 stitched, splitPositions;
  gatherSplit(vertexNormals(s.positions, s.triangles), b.source, stitched);
  gatherSplit(s.positions, b.source, splitPositions);
  // Normals computed on the split mesh itself see only one side's triangles.
  const Points3 naive = vertexNormals(splitPositions, b.triangles);
  double naiveGap = 0;
  int seamPairs = 0;
  for (Index i = 0; i < b.splitVertexCount(); ++i)
    for (Index j = i + 1; j < b.splitVertexCount(); ++j)
      if (b.source[static_cast<std::size_t>(i)] == b.source[static_cast<std::size_t>(j)]) {
        ++seamPairs;
        EXPECT_EQ((stitched.row(i) - stitched.row(j)).norm(), 0.0);
        naiveGap = std::max(naiveGap, (naive.row(i) - naive.row(j)).norm());
      }
  EXPECT_GT(seamPairs, 0);
  EXPECT_GT(naiveGap, 0.1);  // without stitching the shells would tear open
}

TEST(BoxTexcoords, RejectsABadTileSize) {
  const SurfaceMesh cube = test::box({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(boxTexcoords(cube.positions, cube.triangles, 0.0), Error);
  EXPECT_THROW(boxTexcoords(cube.positions, cube.triangles, std::nan("")), Error);
}

}  // namespace
}  // namespace tetskin
