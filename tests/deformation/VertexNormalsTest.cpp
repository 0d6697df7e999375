// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "Shapes.h"
#include "tetskin/deformation/VertexNormals.h"

namespace tetskin {
namespace {

TEST(VertexNormals, BoxCornersPointDiagonallyOutward) {
  const SurfaceMesh box = test::box({-1, -1, -1}, {1, 1, 1});
  const Points3 n = vertexNormals(box.positions, box.triangles);
  for (Index v = 0; v < 8; ++v) {
    EXPECT_NEAR(n.row(v).norm(), 1.0, 1e-12);
    // Outward: same octant as the corner.
    EXPECT_GT(n.row(v).dot(box.positions.row(v)), 0.5);
  }
}

TEST(VertexNormals, AreaWeighting) {
  // Vertex 0 shared by a large triangle in z=0 and a small one in x=0.
  Points3 p(5, 3);
  p << 0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 1, 0, -1, 0;
  Triangles t(2, 3);
  t << 0, 1, 2,  // area 8, normal +z
      0, 3, 4;   // area 0.5, normal -x... (0,0,1)x(0,-1,0) = (1,0,0)
  const Points3 n = vertexNormals(p, t);
  const Eigen::RowVector3d expected = Eigen::RowVector3d(0.5, 0, 8).normalized();
  EXPECT_TRUE(n.row(0).isApprox(expected)) << n.row(0);
  EXPECT_TRUE(n.row(1).isApprox(Eigen::RowVector3d(0, 0, 1)));
}

TEST(VertexNormals, IsolatedVertexGetsZero) {
  Points3 p(4, 3);
  p << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5;
  Triangles t(1, 3);
  t << 0, 1, 2;
  const Points3 n = vertexNormals(p, t);
  EXPECT_EQ(n.row(3), Eigen::RowVector3d::Zero());
  const VertexTriangleAdjacency a = vertexTriangleAdjacency(t, 4);
  EXPECT_EQ(a.offsets, (std::vector<int>{0, 1, 2, 3, 3}));
}

// The normals of a few vertices alone equal vertexNormals' bit for bit
// (binding's tie-break compares signs of dot products with them), on a
// surface with a repeated corner, an isolated vertex and random positions.
TEST(VertexNormals, TheNormalsOfSomeVerticesAreTheWholeSurfacesBitForBit) {
  SurfaceMesh s = test::merge(test::sphere({0, 0, 0}, 1.0, 9, 13), test::box({2, 0, 0}, {3, 1, 2}));
  s.positions += 1e-3 * Points3::Random(s.positions.rows(), 3);
  s.positions.conservativeResize(s.positions.rows() + 1, 3);  // an isolated vertex
  s.positions.bottomRows(1) << 9, 9, 9;
  s.triangles.conservativeResize(s.triangles.rows() + 1, 3);  // a corner twice
  s.triangles.bottomRows(1) << 0, 0, 5;
  const Points3 all = vertexNormals(s.positions, s.triangles);
  const std::vector<Index> some = {0, 3, 5, 77, s.positions.rows() - 1};
  const Points3 few = vertexNormalsOf(s.positions, s.triangles, some);
  ASSERT_EQ(few.rows(), 5);
  for (std::size_t i = 0; i < some.size(); ++i)
    EXPECT_EQ(few.row(static_cast<Index>(i)), all.row(some[i])) << "vertex " << some[i];
  EXPECT_EQ(few.row(4), Eigen::RowVector3d::Zero());
  EXPECT_EQ(vertexNormalsOf(s.positions, s.triangles, {}).rows(), 0);
}

}  // namespace
}  // namespace tetskin
