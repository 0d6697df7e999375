// SPDX-License-Identifier: AGPL-3.0-or-later
// Gmsh volume meshes (.msh) read as tetrahedra: files Gmsh 4.8 wrote (a
// unit sphere, tests/data/gmsh/sphere.geo, in formats 4.1 and 2.2), small
// hand-written ones with known answers, and broken ones named by line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ExpectError.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/GmshFormat.h"

namespace tetskin {
namespace {

void expectSphere(const GmshTetrahedra& read, Index nodes, Index tetrahedra, Index triangles) {
  EXPECT_EQ(read.mesh.nodeCount(), nodes);
  EXPECT_EQ(read.mesh.elementCount(), tetrahedra);
  EXPECT_EQ(read.skippedElements, triangles);  // the physical surface "skin"
  ASSERT_EQ(read.elementTags.size(), static_cast<std::size_t>(tetrahedra));
  for (Index e = 0; e < read.mesh.elementCount(); ++e)
    EXPECT_GT(elementVolume(read.mesh, e), 0) << "element " << e;
  // An inscribed polyhedron of the unit sphere: a little less than 4/3 pi.
  const double sphere = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_LT(meshVolume(read.mesh), sphere);
  EXPECT_GT(meshVolume(read.mesh), 0.95 * sphere);
  const BoundingBox box = boundingBox(read.mesh.nodes);
  EXPECT_NEAR(box.max.z(), 1, 1e-12);  // a pole
  EXPECT_NEAR(box.min.z(), -1, 1e-12);
}

TEST(GmshFormat, ReadsAVolumeMeshGmshWroteInFormat41) {
  expectSphere(readGmshTetrahedra(std::string(TETSKIN_SOURCE_DIR) +
                                  "/tests/data/gmsh/sphere_coarse_v41.msh"),
               205, 679, 320);
}

TEST(GmshFormat, ReadsAVolumeMeshGmshWroteInFormat22) {
  expectSphere(
      readGmshTetrahedra(std::string(TETSKIN_SOURCE_DIR) + "/tests/data/gmsh/sphere_fine_v22.msh"),
      258, 898, 380);
}

// One tetrahedron (tag 7) with a boundary triangle and a point, nodes
// tagged 10, 20, 30, 40 and listed out of order.
constexpr const char* kOneTetrahedron22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$Comments\nmade by hand $Nodes\n$EndComments\n"
    "$Nodes\n4\n"
    "30 0 1 0\n10 0 0 0\n20 1 0 0\n40 0 0 1\n"
    "$EndNodes\n"
    "$Elements\n3\n"
    "1 15 2 0 1 10\n"
    "2 2 2 0 1 10 20 30\n"
    "7 4 2 1 1 10 20 30 40\n"
    "$EndElements\n";

TEST(GmshFormat, MapsNodeTagsAndLeavesLowerElementsOut) {
  const GmshTetrahedra read = parseGmshTetrahedra(kOneTetrahedron22, "t.msh");
  ASSERT_EQ(read.mesh.nodeCount(), 4);
  EXPECT_EQ(read.mesh.nodes.row(0), Eigen::RowVector3d(0, 1, 0));  // tag 30, listed first
  ASSERT_EQ(read.mesh.elementCount(), 1);
  EXPECT_EQ(read.mesh.elements.row(0), Eigen::RowVector4i(1, 2, 0, 3));  // tags 10 20 30 40
  EXPECT_EQ(read.elementTags, (std::vector<long long>{7}));
  EXPECT_EQ(read.skippedElements, 2);
  EXPECT_NEAR(elementVolume(read.mesh, 0), 1.0 / 6.0, 1e-15);
}

TEST(GmshFormat, Format41BlocksAndAQuadraticTetrahedron) {
  const GmshTetrahedra read = parseGmshTetrahedra(
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n"
      "$Nodes\n2 10 1 10\n"
      "3 1 0 4\n1\n2\n3\n4\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n"
      "3 1 0 6\n5\n6\n7\n8\n9\n10\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n0 1 1\n"
      "$EndNodes\n"
      "$Elements\n1 1 3 3\n3 1 11 1\n3 1 2 3 4 5 6 7 8 9 10\n$EndElements\n",
      "q.msh");
  ASSERT_EQ(read.mesh.elementCount(), 1);
  EXPECT_EQ(read.mesh.elements.row(0), Eigen::RowVector4i(0, 1, 2, 3));  // the corners
  EXPECT_EQ(read.elementTags, (std::vector<long long>{3}));
  EXPECT_NEAR(elementVolume(read.mesh, 0), 8.0 / 6.0, 1e-15);
}

// Windows line ends, and nodes with parametric coordinates after x y z
// (Gmsh writes them for nodes on curves and surfaces when asked).
TEST(GmshFormat, WindowsLineEndsAndParametricNodes) {
  const GmshTetrahedra read = parseGmshTetrahedra(
      "$MeshFormat\r\n4.1 0 8\r\n$EndMeshFormat\r\n"
      "$Nodes\r\n1 4 1 4\r\n3 1 1 4\r\n1\r\n2\r\n3\r\n4\r\n"
      "0 0 0 0 0 0\r\n1 0 0 1 0 0\r\n0 1 0 0 1 0\r\n0 0 1 0 0 1\r\n$EndNodes\r\n"
      "$Elements\r\n1 1 1 1\r\n3 1 4 1\r\n1 1 2 3 4\r\n$EndElements\r\n",
      "crlf.msh");
  ASSERT_EQ(read.mesh.elementCount(), 1);
  EXPECT_EQ(read.mesh.nodes.row(3), Eigen::RowVector3d(0, 0, 1));
  EXPECT_NEAR(elementVolume(read.mesh, 0), 1.0 / 6.0, 1e-15);
}

void expectBad(const std::string& content, long line, const std::string& what) {
  test::expectErrorAt([&] { parseGmshTetrahedra(content, "bad.msh"); }, "bad.msh", line, what);
}

std::string withElements(const std::string& elements) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 "
         "1\n$EndNodes\n$Elements\n" +
         elements + "$EndElements\n";
}

TEST(GmshFormat, BrokenFilesAreNamedByLine) {
  expectBad("", 0, "does not start with $MeshFormat");
  expectBad("solid x\nfacet normal 0 0 1\n", 1, "is not a Gmsh mesh (.msh)");
  expectBad("$MeshFormat\n4.1 1 8\n", 2, "is a binary .msh; save it as ASCII (gmsh -bin 0");
  expectBad("$MeshFormat\n4 0 8\n$EndMeshFormat\n", 2,
            "MSH format version 4 is not read here; save as version 4.1 or 2.2");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n", 5,
            "node count 4 is more than the rest of the file can hold");
  expectBad(
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n$EndNodes\n"
      "$Elements\n0\n$EndElements\n",
      7, "$EndNodes after 1 of the 2 nodes announced (truncated section?)");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n", 7,
            "node tag 1 is listed twice");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 nan 0\n$EndNodes\n", 6,
            "coordinate 'nan' is not a finite number");
  expectBad(withElements("1\n1 4 0 1 2 3 9\n"), 13, "element 1: node tag 9 is not in $Nodes");
  expectBad(withElements("1\n5 5 0 1 2 3 4 1 2 3 4\n"), 13,
            "element 5 is a hexahedron: a dataset is made of tetrahedra");
  expectBad(withElements("1\n1 4 0 1 2 3\n"), 13,
            "element 1, a tetrahedron of type 4: expected 4 nodes, found 3");
  expectBad(withElements("1\n1 99 0 1 2 3 4\n"), 13,
            "element 1: element type 99 is not one this reader knows");
  expectBad(withElements("1\n1 2 0 1 2 3\n"), 14, "has no tetrahedra (a surface mesh?");
  expectBad(withElements("2\n1 4 0 1 2 3 4\n"), 14,
            "$EndElements after 1 of the 2 elements announced");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n0\n$EndElements\n", 4,
            "$Elements before $Nodes");
  expectBad("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n3 1 0 1\n1\n0 0 0\n$EndNodes\n",
            8, "the node header counts 2 nodes, the blocks 1");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1000000\n1 0 0 0\n", 5,
            "node count 1000000 is more than the rest of the file can hold");
  expectBad("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Comments\nnever ends\n", 4,
            "$Comments has no $EndComments");
}

}  // namespace
}  // namespace tetskin
