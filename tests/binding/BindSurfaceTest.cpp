// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "SampleData.h"
#include "Shapes.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

void expectWeightsSumToOne(const SurfaceBinding& b) {
  const int k = b.controlsPerVertex();
  for (Index v = 0; v < b.vertexCount(); ++v)
    ASSERT_NEAR(b.weights.row(v).head(k).sum(), 1.0, 1e-12) << "vertex " << v;
}

TEST(BindSurface, ClosestEqualsBruteForceOnTheBunny) {
  const SurfaceMesh surface = readObj(kSampleData + "bunny_8k.obj");
  for (int level = 0; level < sampleDataset().mesh.levelCount(); ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const SurfaceBinding fast = bindSurface(surface, sampleDataset().mesh, level);
    const SurfaceBinding slow = bindClosestBruteForce(surface, sampleDataset().mesh, level);
    EXPECT_EQ(fast.controlIds, slow.controlIds);
    EXPECT_EQ(fast.weights, slow.weights);
    EXPECT_EQ(fast.distance, slow.distance);
    EXPECT_EQ(fast.faceId, slow.faceId);
    expectWeightsSumToOne(fast);
  }
}

// A surface on the control surface itself: every vertex is a node, at
// distance 0 from each face around it, so each is a tie the surface normal
// helps break (bound after the tree's pass, with the normals of the tied
// vertices alone): still the brute force's choice, vertex for vertex.
TEST(BindSurface, ClosestEqualsBruteForceWhereEveryVertexIsATie) {
  const MultiLevelTetMesh& mesh = sampleDataset().mesh;
  const int level = 1;
  const LevelRange& r = mesh.levels[level];
  SurfaceMesh skin;
  skin.positions = mesh.nodes.middleRows(r.firstNode, r.nodeCount);
  skin.triangles = boundaryFaces(extractLevel(mesh, level)).faces;
  const SurfaceBinding fast = bindSurface(skin, mesh, level);
  const SurfaceBinding slow = bindClosestBruteForce(skin, mesh, level);
  EXPECT_EQ(fast.controlIds, slow.controlIds);
  EXPECT_EQ(fast.weights, slow.weights);
  EXPECT_EQ(fast.faceId, slow.faceId);
  // (A node's faces all hold it: the choice among them is the tie-break's.)
  Index nodes = 0;
  for (Index v = 0; v < skin.vertexCount(); ++v)
    nodes += (fast.weights.row(v).head<3>().maxCoeff() > 1 - 1e-9) ? 1 : 0;
  EXPECT_GT(nodes, skin.vertexCount() / 2);
}

// FaceId has one numbering for every method: the element the vertex is
// bound to, in the dataset's numbering as the control ids are; its nodes
// hold the vertex's control ids (three of them for a boundary face, all
// four for embed).
TEST(BindSurface, FaceIdIsTheElementInTheDatasetsNumberingForEveryMethod) {
  const SurfaceMesh surface = readObj(kSampleData + "bunny_8k.obj");
  const MultiLevelTetMesh& mesh = sampleDataset().mesh;
  const int level = 1;
  const LevelRange& range = mesh.levels[level];
  ASSERT_GT(range.firstElement, 0);
  for (BindingMethod method : {BindingMethod::Closest, BindingMethod::Seed, BindingMethod::Embed}) {
    SCOPED_TRACE(toString(method));
    BindingOptions options;
    options.method = method;
    const SurfaceBinding b = bindSurface(surface, mesh, level, options);
    for (Index v = 0; v < b.vertexCount(); ++v) {
      const int element = b.faceId[v];
      ASSERT_GE(element, range.firstElement) << "vertex " << v;
      ASSERT_LT(element, range.firstElement + range.elementCount) << "vertex " << v;
      for (int k = 0; k < b.controlsPerVertex(); ++k) {
        bool held = false;
        for (int corner = 0; corner < 4; ++corner)
          held = held || mesh.elements(element, corner) == b.controlIds(v, k);
        ASSERT_TRUE(held) << "vertex " << v << ": control id " << b.controlIds(v, k)
                          << " is not a node of element " << element;
      }
    }
  }
}

TEST(BindSurface, ClosestEqualsBruteForceOnRandomPoints) {
  // Points scattered around, inside and far outside the control mesh.
  std::mt19937 rng(7);
  std::normal_distribution<double> spread(0, 4);
  SurfaceMesh cloud;
  cloud.positions.resize(3000, 3);
  for (Index i = 0; i < cloud.positions.rows(); ++i)
    cloud.positions.row(i) << spread(rng), 4.8 + spread(rng), spread(rng);
  cloud.positions.row(0) << 1e4, -1e4, 3e3;  // far outside
  cloud.triangles.resize(0, 3);
  const SurfaceBinding fast = bindSurface(cloud, sampleDataset().mesh, 0);
  const SurfaceBinding slow = bindClosestBruteForce(cloud, sampleDataset().mesh, 0);
  EXPECT_EQ(fast.controlIds, slow.controlIds);
  EXPECT_EQ(fast.weights, slow.weights);
  expectWeightsSumToOne(fast);
}

TEST(BindSurface, VertexOnAControlTriangleGetsThatTriangle) {
  const MultiLevelTetMesh& mesh = sampleDataset().mesh;
  const LevelRange& r = mesh.levels[1];
  const BoundaryFaces boundary =
      boundaryFaces(extractLevel(mesh, 1), static_cast<int>(r.firstNode));
  SurfaceMesh points;
  const Index n = std::min<Index>(200, boundary.faces.rows());
  points.positions.resize(n, 3);
  points.triangles.resize(0, 3);
  for (Index f = 0; f < n; ++f) {
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k) c += mesh.nodes.row(boundary.faces(f, k)) / 3.0;
    points.positions.row(f) = c;
  }
  const SurfaceBinding b = bindSurface(points, mesh, 1);
  for (Index f = 0; f < n; ++f) {
    std::array<int, 3> expected = {boundary.faces(f, 0), boundary.faces(f, 1),
                                   boundary.faces(f, 2)};
    std::array<int, 3> got = {b.controlIds(f, 0), b.controlIds(f, 1), b.controlIds(f, 2)};
    EXPECT_EQ(got, expected) << "face " << f;
    EXPECT_NEAR(b.distance[f], 0.0, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.weights(f, k), 1.0 / 3.0, 1e-9);
  }
}

TEST(BindSurface, EveryMethodGivesValidWeights) {
  const SurfaceMesh surface = readObj(kSampleData + "bunny.obj");
  for (BindingMethod method : {BindingMethod::Closest, BindingMethod::Seed, BindingMethod::Embed}) {
    SCOPED_TRACE(toString(method));
    BindingOptions options;
    options.method = method;
    const SurfaceBinding b = bindSurface(surface, sampleDataset().mesh, -1, options);
    EXPECT_EQ(b.level, 2);
    EXPECT_NO_THROW(
        validateBinding(b, surface.vertexCount(), sampleDataset().mesh.nodes.rows(), "b"));
    expectWeightsSumToOne(b);
    const LevelRange& r = sampleDataset().mesh.levels[2];
    EXPECT_GE(b.controlIds.leftCols(b.controlsPerVertex()).minCoeff(), r.firstNode);
    EXPECT_LT(b.controlIds.leftCols(b.controlsPerVertex()).maxCoeff(), r.firstNode + r.nodeCount);
  }
}

TEST(BindSurface, EmbedInsidePointsHaveNonNegativeWeights) {
  TetMesh box = test::unitTetrahedron();
  MultiLevelTetMesh mesh;
  appendLevel(mesh, box);
  SurfaceMesh points;
  points.positions.resize(2, 3);
  points.positions << 0.1, 0.2, 0.3, 2, 2, 2;
  points.triangles.resize(0, 3);
  BindingOptions options;
  options.method = BindingMethod::Embed;
  const SurfaceBinding b = bindSurface(points, mesh, 0, options);
  EXPECT_TRUE(b.weights.row(0).isApprox(Eigen::RowVector4d(0.4, 0.1, 0.2, 0.3)));
  EXPECT_EQ(b.distance[0], 0.0);
  EXPECT_LT(b.minBarycentric[1], 0.0);  // outside: extrapolated
  // Its distance is to the nearest point of the element, (1/3, 1/3, 1/3).
  EXPECT_NEAR(b.distance[1], 5.0 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(b.weights.row(1).sum(), 1.0, 1e-12);
  // The extrapolated weights still reproduce the point (affine exactness).
  Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
  for (int k = 0; k < 4; ++k) p += b.weights(1, k) * box.nodes.row(b.controlIds(1, k));
  EXPECT_TRUE(p.isApprox(Eigen::RowVector3d(2, 2, 2)));
}

TEST(BindSurface, BadInputIsAClearError) {
  SurfaceMesh empty;
  EXPECT_THROW(bindSurface(empty, sampleDataset().mesh, 0), Error);
  SurfaceMesh nan = readObj(kSampleData + "bunny.obj");
  nan.positions(5, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(bindSurface(nan, sampleDataset().mesh, 0), Error);
  EXPECT_THROW(bindSurface(readObj(kSampleData + "bunny.obj"), sampleDataset().mesh, 7), Error);
  // A level whose boundary is all degenerate (collinear nodes).
  MultiLevelTetMesh flat;
  TetMesh t = test::unitTetrahedron();
  t.nodes.col(1).setZero();
  t.nodes.col(2).setZero();
  appendLevel(flat, t);
  EXPECT_THROW(bindSurface(readObj(kSampleData + "bunny.obj"), flat, 0), Error);
}

}  // namespace
}  // namespace tetskin
