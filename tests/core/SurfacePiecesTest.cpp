// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "Shapes.h"
#include "tetskin/core/SurfacePieces.h"

namespace tetskin {
namespace {

// A flat n x n grid of squares, two triangles each.
SurfaceMesh grid(int n) {
  SurfaceMesh mesh;
  mesh.positions.resize((n + 1) * (n + 1), 3);
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) mesh.positions.row(y * (n + 1) + x) << x, y, 0;
  mesh.triangles.resize(2 * n * n, 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.triangles.row(2 * (y * n + x)) << a, b, d;
      mesh.triangles.row(2 * (y * n + x) + 1) << a, d, c;
    }
  return mesh;
}

// Every triangle in one piece, piece sizes within one of each other.
TEST(SurfacePieces, EveryTriangleInOnePieceOfEqualSize) {
  const SurfaceMesh mesh = test::sphere({0, 0, 0}, 1.0, 24, 32);
  for (int pieces : {1, 2, 3, 5, 8}) {
    const std::vector<int> piece = surfacePieces(mesh.positions, mesh.triangles, pieces);
    ASSERT_EQ(piece.size(), static_cast<std::size_t>(mesh.triangleCount()));
    std::vector<Index> sizes(static_cast<std::size_t>(pieces), 0);
    for (int p : piece) {
      ASSERT_GE(p, 0);
      ASSERT_LT(p, pieces);
      ++sizes[static_cast<std::size_t>(p)];
    }
    const auto [smallest, largest] = std::minmax_element(sizes.begin(), sizes.end());
    EXPECT_LE(*largest - *smallest, 1) << pieces << " pieces";
    EXPECT_GT(*smallest, 0);
  }
}

// Compact pieces: a 64 x 64 grid in 4 shares only the vertices along two
// cuts (about 2 x 65), where pieces dealt out by triangle number would
// share most of them.
TEST(SurfacePieces, PiecesAreCompactInSpace) {
  const SurfaceMesh mesh = grid(64);
  const std::vector<int> piece = surfacePieces(mesh.positions, mesh.triangles, 4);
  const std::vector<SurfacePiece> split = splitSurface(mesh.vertexCount(), mesh.triangles, piece);
  ASSERT_EQ(split.size(), 4u);
  Index held = 0;
  for (const SurfacePiece& p : split) held += static_cast<Index>(p.vertices.size());
  const Index shared = held - mesh.vertexCount();
  EXPECT_LE(shared, 2 * 65 + 4);
  EXPECT_GT(shared, 0);
}

// Each piece lists its triangles and exactly the vertices they use, both
// in increasing order; a vertex no triangle uses goes to piece 0.
TEST(SurfacePieces, SplitListsEachPiecesTrianglesAndVertices) {
  SurfaceMesh mesh = grid(10);
  const Index unused = mesh.vertexCount();
  mesh.positions.conservativeResize(unused + 1, 3);
  mesh.positions.row(unused) << 50, 50, 50;
  const std::vector<int> piece = surfacePieces(mesh.positions, mesh.triangles, 3);
  const std::vector<SurfacePiece> split = splitSurface(mesh.vertexCount(), mesh.triangles, piece);
  ASSERT_EQ(split.size(), 3u);
  std::set<Index> everyVertex;
  Index triangles = 0;
  for (std::size_t p = 0; p < split.size(); ++p) {
    const SurfacePiece& s = split[p];
    EXPECT_TRUE(std::is_sorted(s.triangles.begin(), s.triangles.end()));
    EXPECT_TRUE(std::is_sorted(s.vertices.begin(), s.vertices.end()));
    std::set<Index> used;
    for (Index t : s.triangles) {
      EXPECT_EQ(piece[static_cast<std::size_t>(t)], static_cast<int>(p));
      for (int c = 0; c < 3; ++c) used.insert(mesh.triangles(t, c));
    }
    if (p == 0) used.insert(unused);
    EXPECT_EQ(std::vector<Index>(used.begin(), used.end()), s.vertices);
    everyVertex.insert(s.vertices.begin(), s.vertices.end());
    triangles += static_cast<Index>(s.triangles.size());
  }
  EXPECT_EQ(static_cast<Index>(everyVertex.size()), mesh.vertexCount());
  EXPECT_EQ(triangles, mesh.triangleCount());
}

// More pieces than triangles: one triangle each, none empty; fewer than one:
// one piece; the same input gives the same pieces.
TEST(SurfacePieces, PieceCountIsClampedAndTheCutDeterministic) {
  const SurfaceMesh box = test::box({0, 0, 0}, {1, 1, 1});
  const std::vector<int> many = surfacePieces(box.positions, box.triangles, 100);
  EXPECT_EQ(std::set<int>(many.begin(), many.end()).size(), 12u);
  EXPECT_EQ(splitSurface(box.vertexCount(), box.triangles, many).size(), 12u);
  const std::vector<int> none = surfacePieces(box.positions, box.triangles, 0);
  EXPECT_EQ(std::set<int>(none.begin(), none.end()), std::set<int>{0});
  const SurfaceMesh sphere = test::sphere({0, 0, 0}, 1.0);
  EXPECT_EQ(surfacePieces(sphere.positions, sphere.triangles, 6),
            surfacePieces(sphere.positions, sphere.triangles, 6));
  EXPECT_EQ(splitSurface(0, Triangles(0, 3), {}).size(), 1u);
}

}  // namespace
}  // namespace tetskin
