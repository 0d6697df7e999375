// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <vector>

#include "Shapes.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/meshing/Meshers.h"

namespace tetskin {
namespace {

// Sum over faces of (a . (b x c)) / 6: the enclosed volume when all faces
// point outward.
double enclosedVolume(const Points3& nodes, const Triangles& faces, int offset = 0) {
  double v = 0;
  for (Index f = 0; f < faces.rows(); ++f)
    v += nodes.row(faces(f, 0) - offset)
             .dot(nodes.row(faces(f, 1) - offset).cross(nodes.row(faces(f, 2) - offset))) /
         6;
  return v;
}

TEST(BoundaryFaces, SingleTetrahedronHasFourOutwardFaces) {
  const TetMesh m = test::unitTetrahedron();
  const BoundaryFaces b = boundaryFaces(m);
  ASSERT_EQ(b.faces.rows(), 4);
  const Eigen::Vector3d centroid = m.nodes.colwise().mean().transpose();
  for (Index f = 0; f < 4; ++f) {
    const Eigen::Vector3d a = m.nodes.row(b.faces(f, 0)), c1 = m.nodes.row(b.faces(f, 1)),
                          c2 = m.nodes.row(b.faces(f, 2));
    EXPECT_GT((c1 - a).cross(c2 - a).dot((a + c1 + c2) / 3 - centroid), 0) << "face " << f;
    EXPECT_EQ(b.elements[static_cast<std::size_t>(f)], 0);
  }
  EXPECT_NEAR(enclosedVolume(m.nodes, b.faces), 1.0 / 6.0, 1e-15);
}

TEST(BoundaryFaces, InnerFacesAreDropped) {
  TetMesh m;
  m.nodes.resize(5, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  m.elements.resize(2, 4);
  m.elements << 0, 1, 2, 3, 4, 1, 3, 2;
  const BoundaryFaces b = boundaryFaces(m, 10);
  EXPECT_EQ(b.faces.rows(), 6);
  EXPECT_GE(b.faces.minCoeff(), 10);  // ids carry the offset
}

TEST(BoundaryFaces, MeshedBoxBoundaryEnclosesItsVolume) {
  const TetMesh m = tetrahedralizeWithTetGen(test::box({0, 0, 0}, {2, 1, 3}), 1.4);
  const BoundaryFaces b = boundaryFaces(m);
  EXPECT_GT(b.faces.rows(), 12);
  EXPECT_NEAR(enclosedVolume(m.nodes, b.faces), 6.0, 1e-9);
  // Every boundary edge is shared by exactly two boundary faces (closed).
  std::map<std::pair<int, int>, int> edges;
  for (Index f = 0; f < b.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = b.faces(f, k), w = b.faces(f, (k + 1) % 3);
      ++edges[{std::min(u, w), std::max(u, w)}];
    }
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);
}

// The boundary as a surface keeps only the nodes on it, renumbered in
// order, and its winding under any motion of the nodes: a turned and
// stretched copy encloses the turned and stretched volume.
TEST(BoundaryFaces, TheBoundarySurfaceHasOnlyItsNodesAndFollowsThem) {
  const TetMesh grid = test::tetGrid(3, 2, 2, {3, 2, 2});
  const SurfaceMesh surface = boundarySurface(grid);
  EXPECT_EQ(surface.vertexCount(), 4 * 3 * 3 - 2 * 1 * 1);  // all but the 2 inner nodes
  EXPECT_EQ(surface.triangleCount(), boundaryFaces(grid).faces.rows());
  EXPECT_NEAR(enclosedVolume(surface), 12.0, 1e-12);
  std::vector<char> used(static_cast<std::size_t>(surface.vertexCount()), 0);
  for (Index t = 0; t < surface.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(surface.triangles(t, k))] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), surface.vertexCount());
  TetMesh moved = grid;
  const Eigen::Matrix3d map =
      Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
      Eigen::Vector3d(1, 2, 0.5).asDiagonal();
  moved.nodes = (grid.nodes * map.transpose()).eval();
  EXPECT_NEAR(enclosedVolume(boundarySurface(moved)), 12.0 * map.determinant(), 1e-9);
}

}  // namespace
}  // namespace tetskin
