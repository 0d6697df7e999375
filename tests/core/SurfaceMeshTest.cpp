// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

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
