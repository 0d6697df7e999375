// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <vector>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"

namespace tetskin {
namespace {

// A surface triangle floating above the control triangle (0,1,2) of the unit
// tetrahedron, bound by hand.
struct Fixture {
  TetMesh control = test::unitTetrahedron();
  SurfaceMesh surface;
  SurfaceBinding binding;
  Fixture(OffsetMode offset) {
    surface.positions.resize(3, 3);
    surface.positions << 0.2, 0.2, -0.5, 0.6, 0.2, -0.5, 0.2, 0.6, -0.5;
    surface.triangles.resize(1, 3);
    surface.triangles << 0, 2, 1;
    binding.offset = offset;
    binding.resize(3);
    for (Index v = 0; v < 3; ++v) {
      // Control triangle (0,2,1) faces -z (outward for the unit tet).
      binding.controlIds.row(v) << 0, 2, 1, -1;
      const double x = surface.positions(v, 0), y = surface.positions(v, 1);
      binding.weights.row(v) << 1 - x - y, y, x, 0;
      binding.distance[v] = 0.5;
      binding.minBarycentric[v] = binding.weights.row(v).head<3>().minCoeff();
      binding.faceId[v] = 0;
    }
  }
};

TEST(SurfaceDeformer, RestStateReproducesTheSurface) {
  for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement}) {
    Fixture f(offset);
    SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
    Points3 positions, normals;
    deformer.deform(f.control.nodes, positions, normals);
    EXPECT_TRUE(positions.isApprox(f.surface.positions, 1e-14)) << toString(offset);
    for (Index v = 0; v < 3; ++v)
      EXPECT_TRUE(normals.row(v).isApprox(Eigen::RowVector3d(0, 0, -1)));
  }
}

TEST(SurfaceDeformer, TranslationMovesEverythingAlong) {
  for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement}) {
    Fixture f(offset);
    SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
    Points3 moved = f.control.nodes.rowwise() + Eigen::RowVector3d(1, 2, 3);
    Points3 positions, normals;
    deformer.deform(moved, positions, normals);
    EXPECT_TRUE(positions.isApprox(f.surface.positions.rowwise() + Eigen::RowVector3d(1, 2, 3)));
  }
}

TEST(SurfaceDeformer, ScalingTheControlTriangleKeepsTheNormalOffsetLength) {
  Fixture f(OffsetMode::Normal);
  SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
  Points3 scaled = 2.0 * f.control.nodes;
  Points3 positions, normals;
  deformer.deform(scaled, positions, normals);
  // In-plane position scales, the offset along the normal stays 0.5.
  EXPECT_TRUE(positions.row(0).isApprox(Eigen::RowVector3d(0.4, 0.4, -0.5)));
}

TEST(SurfaceDeformer, OutputIsReusedWithoutReallocation) {
  Fixture f(OffsetMode::Normal);
  SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
  Points3 positions(3, 3), normals(3, 3);
  const double* p = positions.data();
  const double* n = normals.data();
  deformer.deform(f.control.nodes, positions, normals);
  EXPECT_EQ(positions.data(), p);
  EXPECT_EQ(normals.data(), n);
}

// Rows owned elsewhere (a VTK array's buffer in the filter and the CPU render
// path): the same values as into a Points3, here through rows 4 wide, so a
// kernel that assumed 3 doubles a row would write the wrong places.
TEST(SurfaceDeformer, WritesIntoRowsOwnedElsewhere) {
  using WideRows = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;
  for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement}) {
    Fixture f(offset);
    SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
    Points3 moved = (f.control.nodes * Eigen::Vector3d(1.5, 0.7, 1.2).asDiagonal()).rowwise() +
                    Eigen::RowVector3d(0.1, -0.2, 0.3);
    moved(3, 0) += 0.4;
    Points3 positions, normals;
    deformer.deform(moved, positions, normals);
    WideRows widePositions = WideRows::Constant(3, 4, 7.0), wideNormals = widePositions;
    deformer.deform(moved, widePositions.leftCols<3>(), wideNormals.leftCols<3>());
    EXPECT_EQ(Points3(widePositions.leftCols<3>()), positions) << toString(offset);
    EXPECT_EQ(Points3(wideNormals.leftCols<3>()), normals) << toString(offset);
    EXPECT_TRUE((widePositions.col(3).array() == 7.0).all()) << toString(offset);
    EXPECT_TRUE((wideNormals.col(3).array() == 7.0).all()) << toString(offset);
  }
}

TEST(SurfaceDeformer, RowsOwnedElsewhereMustMatchTheVertexCount) {
  Fixture f(OffsetMode::Normal);
  SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
  std::vector<double> buffer(4 * 3, 7.0);
  Eigen::Map<Points3> four(buffer.data(), 4, 3), three(buffer.data(), 3, 3);
  EXPECT_THROW(deformer.deform(f.control.nodes, four, three), Error);
  EXPECT_THROW(deformer.deform(f.control.nodes, three, four), Error);
  EXPECT_THROW(deformer.deformPositions(f.control.nodes, four), Error);
  for (double x : buffer) EXPECT_EQ(x, 7.0);
}

TEST(SurfaceDeformer, StateTooSmallIsAnError) {
  Fixture f(OffsetMode::Normal);
  SurfaceDeformer deformer(f.surface, f.binding, f.control.nodes);
  Points3 positions, normals;
  EXPECT_THROW(deformer.deform(f.control.nodes.topRows(2), positions, normals), Error);
}

TEST(SurfaceDeformer, LevelPositionsExpandToTheDataset) {
  MultiLevelTetMesh mesh;
  appendLevel(mesh, test::unitTetrahedron());
  appendLevel(mesh, test::unitTetrahedron());
  Points3 level1 = 3.0 * test::unitTetrahedron().nodes;
  const Points3 all = datasetPositions(mesh, 1, level1, "p.node");
  EXPECT_EQ(all.rows(), 8);
  EXPECT_EQ(all.topRows(4), mesh.nodes.topRows(4));
  EXPECT_EQ(all.bottomRows(4), level1);
  EXPECT_THROW(datasetPositions(mesh, 1, level1.topRows(3), "p.node"), Error);
}

}  // namespace
}  // namespace tetskin
