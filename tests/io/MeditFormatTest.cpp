// SPDX-License-Identifier: AGPL-3.0-or-later
// MEDIT .mesh: round trips through the writer, files as CGAL, fTetWild and
// MMG write them, and broken ones named by line.
#include <gtest/gtest.h>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/io/MeditFormat.h"
#include "tetskin/io/TetrahedraFile.h"

namespace tetskin {
namespace {

MeditMesh twoTetrahedra() {
  MeditMesh m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.1 + 1.0 / 3, 1e-17, -2.5e29;
  m.triangles.resize(1, 3);
  m.triangles << 0, 2, 1;
  m.tetrahedra.resize(2, 4);
  m.tetrahedra << 0, 1, 2, 3, 1, 2, 3, 4;
  return m;
}

TEST(MeditFormat, RoundTripsExactly) {
  test::ScratchDir dir;
  const MeditMesh m = twoTetrahedra();
  writeMedit(dir / "t.mesh", m);
  const MeditMesh back = readMedit(dir / "t.mesh");
  EXPECT_EQ(back.vertices, m.vertices);  // 17 digits: every double back bit for bit
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.tetrahedra, m.tetrahedra);
  EXPECT_EQ(back.skippedRecords, 0);
}

// Keywords in any letter case, a value on the keyword's line or the next,
// comments, and sections read past (CGAL writes Triangles and Tetrahedra;
// MMG and fTetWild add Edges, Corners, Ridges, Required...).
TEST(MeditFormat, ReadsTheSectionsOtherWritersAdd) {
  const MeditMesh m = parseMedit(
      "# made by hand\nMeshVersionFormatted\n2\n\nDimension 3\nvertices\n4\n"
      "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nEdges 1\n1 2 0\nCorners\n2\n1\n2\n"
      "RequiredVertices 1 3\nTRIANGLES\n1\n1 3 2 5\nTetrahedra\n1\n1 2 3 4 7\n"
      "Ridges 1\n1\nNormals\n1\n0 0 1\nNormalAtVertices\n1\n1 1\nEnd\n",
      "mixed.mesh");
  EXPECT_EQ(m.vertices.rows(), 4);
  ASSERT_EQ(m.tetrahedra.rows(), 1);
  EXPECT_EQ(m.tetrahedra.row(0), Eigen::RowVector4i(0, 1, 2, 3));
  EXPECT_EQ(m.triangles.row(0), Eigen::RowVector3i(0, 2, 1));
  EXPECT_EQ(m.skippedRecords, 1 + 2 + 1 + 1 + 1 + 1);
}

void expectBad(const std::string& content, long line, const std::string& what) {
  test::expectErrorAt([&] { parseMedit(content, "bad.mesh"); }, "bad.mesh", line, what);
}

const std::string kHeader = "MeshVersionFormatted 1\nDimension 3\n";
const std::string kFourVertices = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";

TEST(MeditFormat, BrokenFilesAreNamedByLine) {
  expectBad("", 0, "is not a MEDIT mesh (.mesh): it does not start with MeshVersionFormatted");
  expectBad("$MeshFormat\n", 1, "is not a MEDIT mesh");
  expectBad("MeshVersionFormatted 1\nDimension 2\n", 2,
            "dimension 2: a volume mesh has dimension 3");
  expectBad("MeshVersionFormatted 1\nVertices\n1\n0 0 0 0\n", 2, "Vertices before Dimension");
  expectBad(kHeader + "Vertices\n4\n0 0 0 0\n", 4,
            "Vertices count 4 is more than the rest of the file can hold");
  expectBad(kHeader + "Vertices\n2\n0 0 0 0\n1 0 nan 0\n", 6,
            "vertex 2 'nan' is not a finite number");
  expectBad(kHeader + "Vertices\n1\n0 0 1e31 0\n", 5, "vertex 1 has a coordinate");
  expectBad(kHeader + kFourVertices + "Tetrahedra\n1\n1 2 3 5 0\n", 11,
            "tetrahedron of record 1: vertex 5 is out of range (1..4)");
  expectBad(kHeader + kFourVertices + "Tetrahedra\n1\n1 2 3 0 0\n", 11, "vertex 0 is out of range");
  expectBad(kHeader + kFourVertices + "Tetrahedra\n2\n1 2 3 4 0\n1 2 3", 10,
            "Tetrahedra count 2 is more than the rest of the file can hold");
  expectBad(kHeader + kFourVertices + "Tetrahedra\n1\n1 2 3 4\n# cut here, a long comment\n", 12,
            "ends before tetrahedron's reference (truncated file?)");
  expectBad(kHeader + kFourVertices + "Hexahedra\n", 9,
            "has Hexahedra: a dataset is made of tetrahedra");
  expectBad(kHeader + kFourVertices + "SubDomainFromGeom\n1\n", 9,
            "unknown keyword 'SubDomainFromGeom' (this reader takes Dimension, Vertices");
  expectBad(kHeader + "Triangles\n0\n", 3, "Triangles before Vertices");
  expectBad(kHeader + "End\n", 3, "has no Vertices section");
  expectBad(kHeader + kFourVertices + "Vertices\n0\n", 9, "a second Vertices section");
  expectBad(kHeader + "Vertices\n1000000000\n", 4,
            "Vertices count 1000000000 is more than the rest of the file can hold");
}

// The one reader of tetrahedral files a dataset, convert and info use: by
// extension, each element named as its file numbers it.
TEST(TetrahedraFile, ReadsEachFormatByItsExtension) {
  test::ScratchDir dir;
  writeMedit(dir / "t.mesh", twoTetrahedra());
  const TetrahedraFile medit = readTetrahedraFile(dir / "t.mesh");
  EXPECT_EQ(medit.format, "MEDIT");
  EXPECT_EQ(medit.mesh.elementCount(), 2);
  EXPECT_EQ(medit.skippedElements, 1);  // the triangle
  EXPECT_EQ(medit.elementName(1), "tetrahedron 2");
  const TetrahedraFile gmsh = readTetrahedraFile(std::string(TETSKIN_SOURCE_DIR) +
                                                 "/tests/data/gmsh/sphere_coarse_v41_binary.msh");
  EXPECT_EQ(gmsh.format, "Gmsh");
  EXPECT_EQ(gmsh.mesh.elementCount(), 679);
  EXPECT_EQ(gmsh.elementName(0).rfind("element ", 0), 0u);
  EXPECT_TRUE(isTetrahedraFile("a.MSH") && isTetrahedraFile("a.mesh") &&
              isTetrahedraFile("a.node") && isTetrahedraFile("a.ele"));
  EXPECT_FALSE(isTetrahedraFile("a.vtu"));
  // A surface mesh alone is no tetrahedral mesh.
  MeditMesh surface = twoTetrahedra();
  surface.tetrahedra.resize(0, 4);
  writeMedit(dir / "surface.mesh", surface);
  test::expectErrorAt([&] { readTetrahedraFile(dir / "surface.mesh"); },
                      (dir / "surface.mesh").string(), 0, "has no tetrahedra");
}

}  // namespace
}  // namespace tetskin
