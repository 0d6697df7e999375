// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {
namespace {

SurfaceMesh unitSquare() {
  SurfaceMesh m;
  m.positions.resize(4, 3);
  m.positions << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

TEST(SurfaceMesh, AreaOfUnitSquareIsOne) {
  EXPECT_DOUBLE_EQ(surfaceArea(unitSquare()), 1.0);
  EXPECT_NO_THROW(validateSurface(unitSquare(), "square"));
}

// Far from the origin too, where measuring from the origin would lose
// digits; reversing the winding flips the sign.
TEST(SurfaceMesh, EnclosedVolumeOfABoxIsItsVolume) {
  EXPECT_NEAR(enclosedVolume(test::box({0, 0, 0}, {1, 2, 3})), 6.0, 1e-12);
  const Eigen::Vector3d far(1e6, -2e6, 3e6);
  EXPECT_NEAR(enclosedVolume(test::box(far, far + Eigen::Vector3d(0.5, 0.25, 2))), 0.25, 1e-9);
  SurfaceMesh inward = test::box({0, 0, 0}, {1, 1, 1});
  inward.triangles.col(1).swap(inward.triangles.col(2));
  EXPECT_NEAR(enclosedVolume(inward), -1.0, 1e-12);
  EXPECT_EQ(enclosedVolume(SurfaceMesh{}), 0.0);
}

// The square has a normal at every vertex; a fifth vertex on the line of
// two others, in a triangle of zero area only, and a sixth in no triangle
// have none; so has a triangle whose corners repeat.
TEST(SurfaceMesh, NormalGapsCountZeroAreaTrianglesAndVerticesWithoutANormal) {
  EXPECT_TRUE(normalGaps(unitSquare()).empty());
  EXPECT_EQ(describe(normalGaps(unitSquare())), "");
  SurfaceMesh m = unitSquare();
  m.positions.conservativeResize(6, 3);
  m.positions.row(4) << 2, 0, 0;  // on the line through vertices 0 and 1
  m.positions.row(5) << 0, 0, 5;  // in no triangle
  m.triangles.conservativeResize(4, 3);
  m.triangles.row(2) << 0, 1, 4;
  m.triangles.row(3) << 2, 2, 3;
  const NormalGaps gaps = normalGaps(m);
  EXPECT_EQ(gaps.zeroAreaTriangles, 2);
  EXPECT_EQ(gaps.firstZeroAreaTriangle, 2);
  EXPECT_EQ(gaps.verticesWithoutNormal, 2);
  EXPECT_EQ(gaps.firstVertexWithoutNormal, 4);
  EXPECT_EQ(describe(gaps),
            "2 triangles of zero area (first: triangle 2); 2 vertices without a normal, in no "
            "triangle of positive area (first: vertex 4)");
  m.triangles.conservativeResize(3, 3);
  m.positions.conservativeResize(5, 3);
  EXPECT_EQ(describe(normalGaps(m)),
            "1 triangle of zero area (first: triangle 2); 1 vertex without a normal, in no "
            "triangle of positive area (first: vertex 4)");
}

TEST(SurfaceMesh, IndexOutOfRangeNamesTheTriangle) {
  SurfaceMesh m = unitSquare();
  m.triangles(1, 2) = 4;
  try {
    validateSurface(m, "square.obj");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "square.obj");
    EXPECT_NE(std::string(e.what()).find("triangle 1 refers to vertex 4"), std::string::npos)
        << e.what();
  }
}

TEST(SurfaceMesh, NonFiniteCoordinateNamesTheVertex) {
  SurfaceMesh m = unitSquare();
  m.positions(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
      {
        try {
          validateSurface(m, "s");
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("vertex 2"), std::string::npos);
          throw;
        }
      },
      Error);
}

TEST(SurfaceMesh, AttributeCountMustMatchVertexCount) {
  SurfaceMesh m = unitSquare();
  m.normals = Points3::Zero(3, 3);
  EXPECT_THROW(validateSurface(m, "s"), Error);
  m.normals = Points3::Zero(4, 3);
  m.texcoords = Points2::Zero(5, 2);
  EXPECT_THROW(validateSurface(m, "s"), Error);
}

}  // namespace
}  // namespace tetskin
