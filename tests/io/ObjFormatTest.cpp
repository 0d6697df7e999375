// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin {
namespace {

using namespace std::string_view_literals;

void expectObjError(std::string_view content, long line, const std::string& what) {
  test::expectErrorAt([&] { parseObj(content, "bad.obj"); }, "bad.obj", line, what);
}

constexpr std::string_view kQuad =
    "# a unit quad\n"
    "o quad\nmtllib quad.mtl\ng front\ns off\nusemtl red\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "f 1 2 3 4\n";

TEST(ObjFormat, PolygonIsTriangulatedAsAFan) {
  const SurfaceMesh m = parseObj(kQuad, "quad.obj");
  EXPECT_EQ(m.vertexCount(), 4);
  ASSERT_EQ(m.triangleCount(), 2);
  EXPECT_EQ(m.triangles.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.triangles.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_FALSE(m.hasNormals());
  EXPECT_FALSE(m.hasTexcoords());
}

// Twice the area of each triangle along `normal` (positive where it is
// wound counter-clockwise around it).
std::vector<double> windingAreas(const SurfaceMesh& m, const Eigen::Vector3d& normal) {
  std::vector<double> areas;
  for (Index t = 0; t < m.triangleCount(); ++t) {
    const Eigen::Vector3d a = m.positions.row(m.triangles(t, 0)).transpose();
    const Eigen::Vector3d b = m.positions.row(m.triangles(t, 1)).transpose();
    const Eigen::Vector3d c = m.positions.row(m.triangles(t, 2)).transpose();
    areas.push_back((b - a).cross(c - a).dot(normal));
  }
  return areas;
}

TEST(ObjFormat, ANonConvexFaceIsClippedNotFanned) {
  // An L of area 3, counter-clockwise seen from +z, from a corner that does
  // not see the whole of it: its fan laid a triangle over the notch, wound
  // backwards, and the face's triangles covered 5 instead of 3.
  const SurfaceMesh m =
      parseObj("v 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nf 1 2 3 4 5 6\n", "l.obj");
  ASSERT_EQ(m.triangleCount(), 4);
  double total = 0;
  for (double area : windingAreas(m, Eigen::Vector3d::UnitZ())) {
    EXPECT_GT(area, 0);  // each wound as the face, none folded back over it
    total += area / 2;
  }
  EXPECT_DOUBLE_EQ(total, 3);
}

TEST(ObjFormat, ANonConvexFaceInAnyPlaneKeepsItsWinding) {
  // The L in the plane x = 0, wound the other way (facing -x), and a corner
  // on the middle of an edge, which no triangle may take as a third corner
  // of zero area.
  const SurfaceMesh m = parseObj(
      "v 0 0 2\nv 0 1 2\nv 0 1 1\nv 0 2 1\nv 0 2 0\nv 0 1 0\nv 0 0 0\nf 1 2 3 4 5 6 7\n", "l.obj");
  ASSERT_EQ(m.triangleCount(), 5);
  double total = 0;
  for (double area : windingAreas(m, -Eigen::Vector3d::UnitX())) {
    EXPECT_GT(area, 0);
    total += area / 2;
  }
  EXPECT_DOUBLE_EQ(total, 3);
}

TEST(ObjFormat, AllCornerFormsAndNegativeIndices) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\n"
      "vn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "f -3/-3/-1 -2/-2/-1 -1/-1/-1\n";
  const SurfaceMesh m = parseObj(obj, "t.obj");
  EXPECT_EQ(m.vertexCount(), 3);
  EXPECT_EQ(m.triangleCount(), 2);
  EXPECT_EQ(m.triangles.row(0), m.triangles.row(1));
  ASSERT_TRUE(m.hasTexcoords());
  ASSERT_TRUE(m.hasNormals());
  EXPECT_EQ(m.texcoords.row(m.triangles(0, 1)), Eigen::RowVector2d(1, 0));
  EXPECT_EQ(m.normals.row(0), Eigen::RowVector3d(0, 0, 1));

  const SurfaceMesh vOnly =
      parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", "a");
  EXPECT_TRUE(vOnly.hasNormals());
  EXPECT_FALSE(vOnly.hasTexcoords());
  const SurfaceMesh vt = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nf 1/1 2/1 3/1\n", "b");
  EXPECT_TRUE(vt.hasTexcoords());
  EXPECT_FALSE(vt.hasNormals());
}

TEST(ObjFormat, SeamsSplitVerticesWhenAttributesDiffer) {
  // Two triangles share the edge 2-3, but with different texture coordinates.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
      "f 1/1 2/2 3/3\nf 2/4 4/4 3/4\n";
  const SurfaceMesh split = parseObj(obj, "seam.obj");
  EXPECT_EQ(split.vertexCount(), 6);  // 3 + 3: vertices 2 and 3 are split
  EXPECT_EQ(split.triangleCount(), 2);
  const SurfaceMesh plain = parseObj(obj, "seam.obj", ObjReadOptions{.keepAttributes = false});
  EXPECT_EQ(plain.vertexCount(), 4);
  EXPECT_FALSE(plain.hasTexcoords());
  EXPECT_EQ(plain.triangles.row(1), Eigen::RowVector3i(1, 3, 2));
}

TEST(ObjFormat, CrlfCommentsAndMissingFinalNewline) {
  const SurfaceMesh m = parseObj("v 0 0 0 # origin\r\nv 1 0 0\r\n\r\nv 0 1 0\r\nf 1 2 3", "crlf");
  EXPECT_EQ(m.vertexCount(), 3);
  EXPECT_EQ(m.triangleCount(), 1);
  EXPECT_EQ(m.positions(1, 0), 1.0);
}

TEST(ObjFormat, NumberFormats) {
  const SurfaceMesh m = parseObj("v +1 -2. 3e2\nv .5 1E-1 -0\nv 1 1 1 1\nf 1 2 3\n", "n");
  EXPECT_EQ(m.positions.row(0), Eigen::RowVector3d(1, -2, 300));
  EXPECT_EQ(m.positions.row(1), Eigen::RowVector3d(0.5, 0.1, 0));
}

TEST(ObjFormat, MalformedInputNamesFileAndLine) {
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "vertex index 4 is out of range");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", 4, "out of range");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "out of range");
  expectObjError("v 0 0 0\nv 1 zero 0\n", 2, "'zero' is not a number");
  expectObjError("v 0 0 nan\n", 1, "not a finite number");
  expectObjError("v 0 0 1e999\n", 1, "out of range");
  expectObjError("v 0 0 0\nv 0 -2e30 0\n", 2, "vertex has a coordinate of magnitude 2e+30, beyond");
  expectObjError("v 0 0\n", 1, "expected 4 to 7 values");
  expectObjError("v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "at least 3 vertices");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3\n", 4, "malformed face corner");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2 3\n", 4, "texture coordinate index 1");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", 4, "out of range");
  expectObjError("v 0 0 0\nbogus 1 2\n", 2, "unknown OBJ statement 'bogus'");
  expectObjError("v 0 0 0\nv 1\x00 0 0\n"sv, 2, "binary data");
  expectObjError("", 0, "no triangles");
  expectObjError("# only a comment\nv 1 2 3\n", 0, "no triangles");
}

TEST(ObjFormat, BinaryGarbageIsAClearError) {
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919) % 256));
  EXPECT_THROW(parseObj(garbage, "garbage.obj"), Error);
}

TEST(ObjFormat, WriteThenReadIsExact) {
  test::ScratchDir dir;
  SurfaceMesh m;
  m.positions.resize(3, 3);
  m.positions << 0.1, 0.2, 0.3, 1.0 / 3.0, -1e-17, 2.5e10, 0, 1, 0;
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  m.normals = Points3::Zero(3, 3);
  m.normals.col(2).setOnes();
  m.texcoords.resize(3, 2);
  m.texcoords << 0, 0, 1, 0, 0, 1;
  writeObj(dir / "t.obj", m);
  const SurfaceMesh back = readObj(dir / "t.obj");
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.normals, m.normals);
  EXPECT_EQ(back.texcoords, m.texcoords);
}

// A vertex no face uses keeps the texture coordinate and normal of its
// own number, as a file written one per vertex has them (ours do), so such
// a surface reads back as it was written (found by fuzz_obj: it took the
// file's first ones, which changed on the way round).
TEST(ObjFormat, AnUnusedVertexKeepsTheAttributesOfItsNumber) {
  const SurfaceMesh m = parseObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.25\n"
      "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 1 0\n"
      "f 1/1/1 2/2/2 3/3/3\n",
      "u.obj");
  ASSERT_EQ(m.vertexCount(), 4);
  EXPECT_EQ(m.texcoords.row(3), Eigen::RowVector2d(0.5, 0.25));
  EXPECT_EQ(m.normals.row(3), Eigen::RowVector3d(0, 1, 0));
  test::ScratchDir dir;
  writeObj(dir / "u.obj", m);
  const SurfaceMesh back = readObj(dir / "u.obj");
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.texcoords, m.texcoords);
  EXPECT_EQ(back.normals, m.normals);
  // Fewer attributes than positions: the first.
  const SurfaceMesh few =
      parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nvt 0.5 0.5\nf 1/1 2/1 3/1\n", "f.obj");
  EXPECT_EQ(few.texcoords.row(3), Eigen::RowVector2d(0.5, 0.5));
}

TEST(ObjFormat, MissingFileIsAnError) {
  try {
    readObj("/nonexistent/dir/x.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/x.obj: cannot open for reading");
  }
}

TEST(ObjFormat, BundledBunnyReads) {
  const SurfaceMesh m = readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj");
  EXPECT_EQ(m.vertexCount(), 1839);
  EXPECT_EQ(m.triangleCount(), 3674);
  EXPECT_NO_THROW(validateSurface(m, "bunny"));
}

}  // namespace
}  // namespace tetskin
