// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <vector>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/meshing/SurfaceRepair.h"

namespace tetskin {
namespace {

const Eigen::Vector3d kZero(0, 0, 0), kOne(1, 1, 1);

TEST(SurfaceRepair, ClosedBoxNeedsNothing) {
  SurfaceMesh m = test::box(kZero, kOne);
  const RepairReport r = repairSurface(m, "box");
  for (const auto& [key, count] : r.counts())
    if (key.find("put_") == std::string::npos) {
      EXPECT_EQ(count, 0) << key;
    }
  EXPECT_EQ(m.triangleCount(), 12);
  EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-12);
  EXPECT_TRUE(boundaryLoops(m).empty());
  EXPECT_EQ(nonManifoldEdgeCount(m), 0);
}

TEST(SurfaceRepair, DuplicatedVerticesAreWelded) {
  SurfaceMesh m = test::soup(test::box(kZero, kOne));
  ASSERT_EQ(m.vertexCount(), 36);
  EXPECT_EQ(boundaryLoops(m).size(), 12u);  // every triangle is an island
  const RepairReport r = repairSurface(m, "soup");
  EXPECT_EQ(r.weldedVertices, 28);
  EXPECT_EQ(r.unusedVertices, 28);
  EXPECT_EQ(m.vertexCount(), 8);
  EXPECT_EQ(m.triangleCount(), 12);
  EXPECT_EQ(r.openTrianglesRemoved, 0);
}

TEST(SurfaceRepair, DegenerateAndDuplicateTrianglesAreDropped) {
  SurfaceMesh m = test::box(kZero, kOne);
  m.triangles.conservativeResize(15, 3);
  m.triangles.row(12) << 0, 0, 1;  // repeated vertex
  m.triangles.row(13) << 0, 1, 1;
  m.triangles.row(14) << 3, 2, 1;  // same vertices as triangle 1, opposite winding
  m.positions.conservativeResize(9, 3);
  m.positions.row(8) << 0.5, 0, 0;  // on the edge 0-1: zero area
  m.triangles.conservativeResize(16, 3);
  m.triangles.row(15) << 0, 8, 1;
  EXPECT_EQ(removeDegenerateTriangles(m, 1e-14), 3);
  EXPECT_EQ(removeDuplicateTriangles(m), 1);
  EXPECT_EQ(m.triangleCount(), 12);
  EXPECT_EQ(removeUnusedVertices(m), 1);
}

TEST(SurfaceRepair, OrientationIsMadeConsistentAndOutward) {
  SurfaceMesh m = test::box(kZero, kOne);
  std::swap(m.triangles(3, 1), m.triangles(3, 2));
  std::swap(m.triangles(7, 1), m.triangles(7, 2));
  OrientationResult o = orientConsistently(m);
  EXPECT_EQ(o.flippedTriangles, 2);
  EXPECT_TRUE(o.orientable);
  EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-12);
  // An inside-out box is turned outward.
  SurfaceMesh inverted = test::box(kZero, kOne);
  inverted.triangles.col(1).swap(inverted.triangles.col(2));
  o = orientConsistently(inverted);
  EXPECT_EQ(o.invertedComponents, 1);
  EXPECT_NEAR(enclosedVolume(inverted), 1.0, 1e-12);
}

// The parts of a hollow box keep their windings relative to the outermost
// one, which turns outward: the cavity stays a cavity.
TEST(SurfaceRepair, AHollowShapeStaysHollow) {
  SurfaceMesh inner = test::box(Eigen::Vector3d::Constant(0.25), Eigen::Vector3d::Constant(0.75));
  inner.triangles.col(1).swap(inner.triangles.col(2));  // facing into the cavity
  SurfaceMesh hollow = test::merge(test::box(kZero, kOne), inner);
  RepairReport r = repairSurface(hollow, "hollow");
  EXPECT_EQ(r.cavities, 1);
  EXPECT_EQ(r.invertedComponents, 0);
  EXPECT_NEAR(enclosedVolume(hollow), 1.0 - 0.125, 1e-12);
  // Inside out throughout: both parts turn, the cavity stays.
  SurfaceMesh insideOut = hollow;
  insideOut.triangles.col(1).swap(insideOut.triangles.col(2));
  r = repairSurface(insideOut, "inside out");
  EXPECT_EQ(r.cavities, 1);
  EXPECT_EQ(r.invertedComponents, 2);
  EXPECT_NEAR(enclosedVolume(insideOut), 1.0 - 0.125, 1e-12);
  // Wound alike, the inner box is a part of the solid, as given.
  SurfaceMesh filled =
      test::merge(test::box(kZero, kOne),
                  test::box(Eigen::Vector3d::Constant(0.25), Eigen::Vector3d::Constant(0.75)));
  r = repairSurface(filled, "filled");
  EXPECT_EQ(r.cavities, 0);
  EXPECT_NEAR(enclosedVolume(filled), 1.0 + 0.125, 1e-12);
}

// A part keeps the winding most of its triangles had.
TEST(SurfaceRepair, APartKeepsItsMajorityWinding) {
  SurfaceMesh inner = test::box(Eigen::Vector3d::Constant(0.25), Eigen::Vector3d::Constant(0.75));
  inner.triangles.col(1).swap(inner.triangles.col(2));
  std::swap(inner.triangles(0, 1), inner.triangles(0, 2));  // its first triangle the odd one out
  SurfaceMesh hollow = test::merge(test::box(kZero, kOne), inner);
  const RepairReport r = repairSurface(hollow, "hollow");
  EXPECT_EQ(r.flippedTriangles, 1);
  EXPECT_EQ(r.cavities, 1);
  EXPECT_NEAR(enclosedVolume(hollow), 1.0 - 0.125, 1e-12);
}

// A unit cube whose faces are split into n x n squares of two triangles,
// turned off the axes (a CAD model's flat faces): closed and free of
// intersections, though its faces are flat only up to rounding. Repair
// found intersections there, and its collapse left nothing of the cube.
TEST(SurfaceRepair, ATurnedFinelySplitCubeNeedsNoRepair) {
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(0.61, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(0.37, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  constexpr int n = 3;
  SurfaceMesh cube;
  std::vector<Eigen::Vector3d> points;
  std::map<std::array<int, 3>, int> ids;  // grid coordinates -> vertex
  auto vertex = [&](std::array<int, 3> g) {
    const auto [it, added] = ids.emplace(g, static_cast<int>(points.size()));
    if (added) points.push_back(turn * Eigen::Vector3d(g[0], g[1], g[2]) / n);
    return it->second;
  };
  std::vector<std::array<int, 3>> triangles;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= n; side += n)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            std::array<int, 3> g{};
            g[axis] = side, g[(axis + 1) % 3] = a, g[(axis + 2) % 3] = b;
            return vertex(g);
          };
          const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
          if (side == n) {
            triangles.push_back({a, b, c});
            triangles.push_back({a, c, d});
          } else {
            triangles.push_back({a, c, b});
            triangles.push_back({a, d, c});
          }
        }
  cube.positions.resize(static_cast<Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
    cube.positions.row(static_cast<Index>(v)) = points[v].transpose();
  cube.triangles.resize(static_cast<Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) cube.triangles(static_cast<Index>(t), k) = triangles[t][k];
  EXPECT_TRUE(findSelfIntersections(cube).empty());
  const RepairReport r = repairSurface(cube, "cube");
  EXPECT_EQ(r.intersectingPairs, 0);
  EXPECT_EQ(cube.triangleCount(), 6 * 2 * n * n);
  EXPECT_NEAR(enclosedVolume(cube), 1.0, 1e-12);
}

// The unit cube with its top face (z = 1) split at the middle of its front
// edge, where the front face (y = 0) is not: a T-junction, open on both
// sides of the seam though nothing is missing. `offset` moves the middle
// vertex along +z, off the front face's edge.
SurfaceMesh cubeWithATJunction(double offset) {
  SurfaceMesh m;
  m.positions.resize(9, 3);
  m.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0,
      1 + offset;
  m.triangles.resize(13, 3);
  m.triangles << 0, 2, 1, 0, 3, 2, 4, 8, 7, 8, 6, 7, 8, 5, 6, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2,
      3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7;
  return m;
}

TEST(SurfaceRepair, ATJunctionIsSplitAndTheSurfaceCloses) {
  // (Before, the seam's open edges ate the cube: "1 hole(s) ... left nothing".)
  SurfaceMesh m = cubeWithATJunction(0);
  ASSERT_EQ(boundaryLoops(m).size(), 1u);
  const RepairReport r = repairSurface(m, "t.obj");
  EXPECT_EQ(r.tJunctionsSplit, 1);
  EXPECT_EQ(r.holes, 0);
  EXPECT_EQ(r.openTrianglesRemoved, 0);
  EXPECT_EQ(r.flippedTriangles, 0);  // the split keeps the winding
  EXPECT_EQ(m.triangleCount(), 14);
  EXPECT_TRUE(boundaryLoops(m).empty());
  EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-12);
}

TEST(SurfaceRepair, AVertexWithinTheToleranceOfAnEdgeSplitsIt) {
  // A float32 export rounds the T-junction's vertex off the edge.
  SurfaceMesh m = cubeWithATJunction(1e-8);
  EXPECT_EQ(splitTJunctions(m, 1e-6), 1);
  EXPECT_TRUE(boundaryLoops(m).empty());
  EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-7);
}

TEST(SurfaceRepair, AVertexOffTheEdgeIsAGapNotATJunction) {
  SurfaceMesh m = cubeWithATJunction(0.01);
  EXPECT_EQ(splitTJunctions(m, 1e-6), 0);
  EXPECT_EQ(m.triangleCount(), 13);
  EXPECT_THROW(repairSurface(m, "gap.obj"), Error);
}

TEST(SurfaceRepair, SeamsSplitDifferentlyOnEitherSideAreSplitOnBoth) {
  // The top face's front edge has vertices at 1/3 and 2/3, the front face's
  // top edge one at 1/2: each side's vertices split the other side's edges.
  SurfaceMesh m = cubeWithATJunction(0);  // (its vertex 8 moves to the front face)
  m.positions.conservativeResize(11, 3);
  m.positions.row(9) << 1.0 / 3, 0, 1;
  m.positions.row(10) << 2.0 / 3, 0, 1;
  // Top face (seen from +z): 4, 9, 10, 5 along the front, 6 and 7 behind.
  m.triangles.row(2) << 4, 9, 7;
  m.triangles.row(3) << 9, 10, 7;
  m.triangles.row(4) << 10, 5, 6;
  m.triangles.row(6) << 0, 5, 8;  // the front face's triangle under the seam
  m.triangles.conservativeResize(15, 3);
  m.triangles.row(13) << 10, 6, 7;
  m.triangles.row(14) << 0, 8, 4;
  ASSERT_EQ(boundaryLoops(m).size(), 1u);
  EXPECT_EQ(splitTJunctions(m, 1e-9), 3);
  EXPECT_TRUE(boundaryLoops(m).empty());
  EXPECT_EQ(nonManifoldEdgeCount(m), 0);
  SurfaceMesh wound = m;
  EXPECT_EQ(orientConsistently(wound).flippedTriangles, 0);
  EXPECT_NEAR(enclosedVolume(m), 1.0, 1e-12);
}

TEST(SurfaceRepair, DanglingTriangleIsRemoved) {
  // The report's case: a triangle hanging off an edge of a closed surface.
  SurfaceMesh m = test::box(kZero, kOne);
  m.positions.conservativeResize(9, 3);
  m.positions.row(8) << 0.5, -1, -1;
  m.triangles.conservativeResize(13, 3);
  m.triangles.row(12) << 0, 1, 8;
  EXPECT_EQ(nonManifoldEdgeCount(m), 1);
  const RepairReport r = repairSurface(m, "dangling");
  EXPECT_EQ(r.openTrianglesRemoved, 1);
  EXPECT_EQ(r.holes, 1);
  EXPECT_EQ(m.triangleCount(), 12);
  EXPECT_EQ(m.vertexCount(), 8);
}

TEST(SurfaceRepair, SurfaceWithAHoleCannotBeRepaired) {
  SurfaceMesh m = test::box(kZero, kOne);
  m.triangles.conservativeResize(10, 3);  // drop the x = hi face
  ASSERT_EQ(boundaryLoops(m).size(), 1u);
  EXPECT_EQ(boundaryLoops(m)[0].size(), 4u);
  try {
    repairSurface(m, "holey.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "holey.obj");
    EXPECT_NE(e.message().find("1 hole"), std::string::npos) << e.what();
  }
}

TEST(SurfaceRepair, InterpenetratingBoxesAreDetectedAndCollapsed) {
  SurfaceMesh m = test::merge(test::box(kZero, kOne), test::box(Eigen::Vector3d(0.5, 0.3, 0.2),
                                                                Eigen::Vector3d(1.5, 1.3, 1.2)));
  const auto pairs = findSelfIntersections(m);
  EXPECT_GT(pairs.size(), 4u);
  for (const auto& [a, b] : pairs) EXPECT_LT(a, b);
  // Separate boxes do not intersect.
  const SurfaceMesh apart = test::merge(
      test::box(kZero, kOne), test::box(Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(3, 3, 3)));
  EXPECT_TRUE(findSelfIntersections(apart).empty());
  // The report's collapse either removes every intersection or the surface is
  // declared unrepairable; a repaired surface must be closed and clean.
  try {
    const RepairReport r = repairSurface(m, "two boxes");
    EXPECT_GT(r.intersectingPairs, 0);
    EXPECT_GT(r.collapsedTriangles, 0);
    EXPECT_TRUE(findSelfIntersections(m).empty());
    EXPECT_TRUE(boundaryLoops(m).empty());
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("cannot be repaired"), std::string::npos) << e.what();
  }
}

TEST(SurfaceRepair, CollapseMovesTheFirstTriangleOntoTheSecond) {
  // (Equal triangles: a tie, which goes to the first.)
  SurfaceMesh m = test::merge(test::box(kZero, kOne), test::box(kZero, kOne));
  const std::vector<std::pair<int, int>> pairs = {{0, 12}};
  EXPECT_EQ(collapseIntersections(m, pairs), 1);
  EXPECT_EQ(m.triangles(0, 0), m.triangles(0, 1));
  EXPECT_EQ(m.triangles(0, 1), m.triangles(0, 2));
}

TEST(SurfaceRepair, CollapseMovesTheTriangleWhoseVerticesMoveLeast) {
  // A small triangle through a large one, in either order of the pair: the
  // small one collapses onto the large one's nearest vertex.
  SurfaceMesh m;
  m.positions.resize(6, 3);
  m.positions << 0, 0, 0, 1, 0, 0, 0, 1, 0,  // large, in z = 0
      0.1, 0.1, -0.01, 0.11, 0.1, 0.01, 0.1, 0.11, 0.01;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 3, 4, 5;
  for (const std::pair<int, int>& pair : {std::pair{0, 1}, std::pair{1, 0}}) {
    SurfaceMesh c = m;
    ASSERT_EQ(findSelfIntersections(c).size(), 1u);
    EXPECT_EQ(collapseIntersections(c, {pair}), 1);
    EXPECT_EQ(c.triangles.row(0), m.triangles.row(0));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(c.triangles(1, k), 0) << k;  // the vertex at the origin
  }
}

// The collapse is meant for small defects; overlapping parts come out of it
// another shape, which the report's volumes show and collapseWarning names.
TEST(SurfaceRepair, CollapsingOverlappingPartsChangesTheVolumeAndIsWarnedAbout) {
  SurfaceMesh m = test::merge(test::box(kZero, kOne), test::box(Eigen::Vector3d(0.5, 0.5, 0.5),
                                                                Eigen::Vector3d(1.5, 1.5, 1.5)));
  const RepairReport r = repairSurface(m, "cubes.obj");
  ASSERT_GT(r.collapsedTriangles, 0);
  EXPECT_NEAR(r.volumeBeforeCollapse, 2.0, 1e-12);  // the shared eighth counted twice
  EXPECT_NEAR(r.volumeAfterCollapse, enclosedVolume(m), 1e-12);
  EXPECT_NEAR(r.collapseVolumeChange(), (r.volumeAfterCollapse - 2.0) / 2.0, 1e-12);
  EXPECT_GT(std::abs(r.collapseVolumeChange()), kCollapseVolumeTolerance);
  const std::string warning = collapseWarning(r, "cubes.obj");
  EXPECT_EQ(warning.rfind("cubes.obj: collapsing " + std::to_string(r.intersectingPairs) +
                              " intersecting pair(s) of triangles changed the enclosed volume by ",
                          0),
            0u)
      << warning;
  EXPECT_NE(warning.find("% (2 to "), std::string::npos) << warning;

  // A small part poking out of a corner, like a scan's defect: its
  // triangles collapse onto the large box's (not the other way round), so
  // the volume hardly changes and nothing is warned about.
  SurfaceMesh corner =
      test::merge(test::box(kZero, kOne),
                  test::box(Eigen::Vector3d(0.99, 0.99, 0.99), Eigen::Vector3d(1.01, 1.01, 1.01)));
  const RepairReport small = repairSurface(corner, "corner.obj");
  ASSERT_GT(small.collapsedTriangles, 0);
  EXPECT_NEAR(small.volumeBeforeCollapse, 1.0 + 8e-6, 1e-12);
  EXPECT_LT(std::abs(small.collapseVolumeChange()), kCollapseVolumeTolerance);
  EXPECT_EQ(collapseWarning(small, "corner.obj"), "");

  // Nothing intersected: no volumes, no change, no warning.
  SurfaceMesh box = test::box(kZero, kOne);
  const RepairReport clean = repairSurface(box, "box.obj");
  EXPECT_EQ(clean.volumeBeforeCollapse, 0);
  EXPECT_EQ(clean.collapseVolumeChange(), 0);
  EXPECT_EQ(collapseWarning(clean, "box.obj"), "");
}

TEST(SurfaceRepair, EmptyAndNonFiniteInputsAreErrors) {
  SurfaceMesh empty;
  EXPECT_THROW(repairSurface(empty, "empty"), Error);
  SurfaceMesh m = test::box(kZero, kOne);
  m.positions(3, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(repairSurface(m, "nan"), Error);
}

// A box missing one face (two triangles): the hole's patch is a fan from
// the rim's centre, wound as its neighbours, which closes the box again;
// a patch larger than allowed leaves the hole open.
TEST(SurfaceRepair, FillHolesClosesHolesUpToAnArea) {
  SurfaceMesh open = test::box({0, 0, 0}, {1, 1, 1});
  open.triangles.conservativeResize(10, 3);  // (the x = hi face gone)
  SurfaceMesh kept = open;
  EXPECT_EQ(fillHoles(kept, 0.99), 0);
  EXPECT_EQ(boundaryLoops(kept).size(), 1u);
  EXPECT_EQ(fillHoles(open, 1.01), 1);
  EXPECT_TRUE(boundaryLoops(open).empty());
  EXPECT_EQ(open.triangleCount(), 14);  // 4 rim edges, one fan triangle each
  EXPECT_EQ(open.vertexCount(), 9);
  EXPECT_NEAR(enclosedVolume(open), 1.0, 1e-12);  // wound outward, as the box
  EXPECT_EQ(orientConsistently(open).flippedTriangles, 0);
}

}  // namespace
}  // namespace tetskin
