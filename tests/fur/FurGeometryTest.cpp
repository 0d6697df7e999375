// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <vector>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/fur/FurGeometry.h"

namespace tetskin {
namespace {

TEST(FurGeometry, ShellsStackInsideOutOverTheSplitSurface) {
  const SurfaceMesh cube = test::box({0, 0, 0}, {1, 1, 1});
  const BoxTexturedSurface box = boxTexcoords(cube.positions, cube.triangles, 0.5);
  const FurMesh m = shellMesh(box, shellHeights(4));
  ASSERT_EQ(m.vertexCount(), 4 * 24);
  ASSERT_EQ(m.triangles.rows(), 4 * 12);
  for (Index t = 0; t < m.triangles.rows(); ++t) {
    const float h = m.height[static_cast<std::size_t>(m.triangles(t, 0))];
    EXPECT_FLOAT_EQ(h, static_cast<float>(t / 12 + 1) / 4);  // triangle order = shell order
    for (int k = 1; k < 3; ++k) EXPECT_EQ(m.height[static_cast<std::size_t>(m.triangles(t, k))], h);
  }
}

TEST(FurGeometry, FurPointsRiseAlongTheStitchedNormals) {
  const SurfaceMesh cube = test::box({-1, -1, -1}, {1, 1, 1});
  const BoxTexturedSurface box = boxTexcoords(cube.positions, cube.triangles, 0.5);
  const FurMesh m = shellMesh(box, shellHeights(2));
  const Points3 normals = vertexNormals(cube.positions, cube.triangles);
  Points3 out;
  furPoints(cube.positions, normals, Points3::Zero(8, 3), m, 0.1, {}, out);
  for (Index i = 0; i < m.vertexCount(); ++i) {
    const Index v = m.source[static_cast<std::size_t>(i)];
    const Eigen::RowVector3d expected =
        cube.positions.row(v) + 0.1 * m.height[static_cast<std::size_t>(i)] * normals.row(v);
    EXPECT_TRUE(out.row(i).isApprox(expected));
  }
  // All copies of a corner coincide: no gap at the seams.
  for (Index i = 0; i < m.vertexCount(); ++i)
    for (Index j = 0; j < m.vertexCount(); ++j)
      if (m.source[static_cast<std::size_t>(i)] == m.source[static_cast<std::size_t>(j)] &&
          m.height[static_cast<std::size_t>(i)] == m.height[static_cast<std::size_t>(j)]) {
        EXPECT_EQ(out.row(i), out.row(j));
      }
}

TEST(FurGeometry, FurPointsAndNormalsWriteIntoRowsOwnedElsewhere) {
  const SurfaceMesh cube = test::box({-1, -1, -1}, {1, 1, 1});
  const BoxTexturedSurface box = boxTexcoords(cube.positions, cube.triangles, 0.5);
  const FurMesh m = shellMesh(box, shellHeights(3));
  const Points3 normals = vertexNormals(cube.positions, cube.triangles);
  const Points3 velocities = Points3::Constant(8, 3, 0.5);
  Points3 expected;
  furPoints(cube.positions, normals, velocities, m, 0.1, {}, expected);
  // Rows of a larger buffer, as a VTK array's memory is to the caller.
  const Index n = m.vertexCount();
  std::vector<double> buffer(static_cast<std::size_t>(3 * (n + 2)), -7.0);
  furPoints(cube.positions, normals, velocities, m, 0.1, {},
            Eigen::Map<Points3>(buffer.data() + 3, n, 3));
  EXPECT_EQ(Eigen::Map<Points3>(buffer.data() + 3, n, 3), expected);
  EXPECT_EQ(buffer.front(), -7.0);  // nothing outside the rows
  EXPECT_EQ(buffer[static_cast<std::size_t>(3 * (n + 1))], -7.0);
  Points3 furNormalRows(n, 3);
  furNormals(normals, m, furNormalRows);
  for (Index i = 0; i < n; ++i)
    EXPECT_EQ(furNormalRows.row(i), normals.row(m.source[static_cast<std::size_t>(i)]));
  Points3 tooFew(n - 1, 3);
  EXPECT_THROW(furPoints(cube.positions, normals, velocities, m, 0.1, {}, Points3Ref(tooFew)),
               Error);
  EXPECT_THROW(furNormals(normals, m, tooFew), Error);
}

TEST(FurGeometry, OneFinPerEdgeFromRootToTip) {
  const SurfaceMesh cube = test::box({0, 0, 0}, {1, 1, 1});
  const FurMesh fins = finMesh(cube.positions, cube.triangles, 0.5, 3);
  EXPECT_EQ(fins.vertexCount(), 4 * 18);  // a closed 12-triangle box has 18 edges
  EXPECT_EQ(fins.triangles.rows(), 2 * 18);
  for (Index e = 0; e < 18; ++e) {
    const auto base = static_cast<std::size_t>(4 * e);
    EXPECT_EQ(fins.height[base], 0.0f);
    EXPECT_EQ(fins.height[base + 2], 1.0f);
    EXPECT_EQ(fins.source[base], fins.source[base + 3]);
    EXPECT_NE(fins.source[base], fins.source[base + 1]);
    // The texture span is the edge length in tiles.
    const double span = fins.texcoords(4 * e + 1, 0) - fins.texcoords(4 * e, 0);
    EXPECT_NEAR(
        span * 0.5,
        (cube.positions.row(fins.source[base + 1]) - cube.positions.row(fins.source[base])).norm(),
        1e-12);
  }
}

TEST(FurGeometry, AdaptiveShellCountFollowsTheFursPixelHeight) {
  EXPECT_EQ(adaptiveShellCount(100, 4, 16), 16);
  EXPECT_EQ(adaptiveShellCount(9.2, 4, 16), 10);
  EXPECT_EQ(adaptiveShellCount(1, 4, 16), 4);
  EXPECT_EQ(adaptiveShellCount(0, 4, 16), 4);
  EXPECT_EQ(adaptiveShellCount(5, 20, 16), 16);  // min clamped to max
}

}  // namespace
}  // namespace tetskin
