// SPDX-License-Identifier: AGPL-3.0-or-later
// Gmsh volume meshes (.msh) read as tetrahedra: files Gmsh 4.8 wrote (a
// unit sphere, tests/data/gmsh/sphere.geo, in formats 4.1 and 2.2), small
// hand-written ones with known answers, and broken ones named by line.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "ExpectError.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/GmshFormat.h"
#include "tetskin/io/TetGenFormat.h"

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
  expectBad("$MeshFormat\n4.1 2 8\n", 2, "file type 2 is neither 0 (ASCII) nor 1 (binary)");
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

// Binary files Gmsh 4.8 wrote of the same sphere as the ASCII 4.1 file
// (gmsh sphere.geo -3 -bin -format msh41 / msh22): the same mesh.
TEST(GmshFormat, ReadsBinaryFilesGmshWroteInFormats41And22) {
  const std::string dir = std::string(TETSKIN_SOURCE_DIR) + "/tests/data/gmsh/";
  const GmshTetrahedra ascii = readGmshTetrahedra(dir + "sphere_coarse_v41.msh");
  for (const char* name : {"sphere_coarse_v41_binary.msh", "sphere_coarse_v22_binary.msh"}) {
    SCOPED_TRACE(name);
    const GmshTetrahedra binary = readGmshTetrahedra(dir + name);
    expectSphere(binary, 205, 679, 320);
    // (The ASCII file holds 16 significant digits, the binary one all 17.)
    ASSERT_EQ(binary.mesh.nodes.rows(), ascii.mesh.nodes.rows());
    EXPECT_LT((binary.mesh.nodes - ascii.mesh.nodes).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_EQ(binary.mesh.elements, ascii.mesh.elements);
    EXPECT_EQ(binary.elementTags, ascii.elementTags);
  }
}

// A binary .msh as Gmsh lays it out, written here in either byte order
// and size_t width (Gmsh writes its machine's; a big-endian machine's file
// cannot be made on this one): two tetrahedra sharing a face, a boundary
// triangle, node tags out of order, in 4.1 parametric nodes too.
class BinaryMsh {
 public:
  BinaryMsh(bool bigEndian, int sizeBytes)
      : swap_(bigEndian != (std::endian::native == std::endian::big)), size_(sizeBytes) {}
  void text(const std::string& s) { out_ += s; }
  void i32(std::int32_t v) { put(v); }
  void f64(double v) { put(v); }
  void size(std::uint64_t v) {
    if (size_ == 8)
      put(v);
    else
      put(static_cast<std::uint32_t>(v));
  }
  const std::string& bytes() const { return out_; }

 private:
  template <typename T>
  void put(T v) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    if (swap_) std::reverse(bytes, bytes + sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  bool swap_;
  int size_;
  std::string out_;
};

// Nodes tagged 10..50 (listed 30 first), tets (10 20 30 40) and (20 30 40 50).
const double kPoints[5][3] = {{0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}};
const int kTags[5] = {30, 10, 20, 40, 50};

std::string binary22(bool bigEndian) {
  BinaryMsh m(bigEndian, 8);
  m.text("$MeshFormat\n2.2 1 8\n");
  m.i32(1);
  m.text("\n$EndMeshFormat\n$Nodes\n5\n");
  for (int i = 0; i < 5; ++i) {
    m.i32(kTags[i]);
    for (double x : kPoints[i]) m.f64(x);
  }
  m.text("\n$EndNodes\n$Elements\n3\n");
  m.i32(2), m.i32(1), m.i32(2);  // one triangle, two tags
  m.i32(1), m.i32(0), m.i32(1), m.i32(10), m.i32(20), m.i32(30);
  m.i32(4), m.i32(2), m.i32(2);  // two tetrahedra
  m.i32(7), m.i32(0), m.i32(1), m.i32(10), m.i32(20), m.i32(30), m.i32(40);
  m.i32(8), m.i32(0), m.i32(1), m.i32(20), m.i32(40), m.i32(30), m.i32(50);
  m.text("\n$EndElements\n");
  return m.bytes();
}

std::string binary41(bool bigEndian, int sizeBytes) {
  BinaryMsh m(bigEndian, sizeBytes);
  m.text("$MeshFormat\n4.1 1 " + std::to_string(sizeBytes) + "\n");
  m.i32(1);
  m.text("\n$EndMeshFormat\n$Entities\n");
  m.size(0), m.size(0), m.size(0), m.size(0);
  m.text("\n$EndEntities\n$Nodes\n");
  m.size(2), m.size(5), m.size(10), m.size(50);
  // Block 1: a surface entity's 2 nodes with parametric (u, v).
  m.i32(2), m.i32(1), m.i32(1), m.size(2);
  m.size(kTags[0]), m.size(kTags[1]);
  for (int i = 0; i < 2; ++i) {
    for (double x : kPoints[i]) m.f64(x);
    m.f64(0.5), m.f64(0.25);
  }
  // Block 2: the volume's other 3, not parametric.
  m.i32(3), m.i32(1), m.i32(0), m.size(3);
  for (int i = 2; i < 5; ++i) m.size(kTags[i]);
  for (int i = 2; i < 5; ++i)
    for (double x : kPoints[i]) m.f64(x);
  m.text("\n$EndNodes\n$Elements\n");
  m.size(2), m.size(3), m.size(1), m.size(8);
  m.i32(2), m.i32(1), m.i32(2), m.size(1);
  m.size(1), m.size(10), m.size(20), m.size(30);
  m.i32(3), m.i32(1), m.i32(4), m.size(2);
  m.size(7), m.size(10), m.size(20), m.size(30), m.size(40);
  m.size(8), m.size(20), m.size(40), m.size(30), m.size(50);
  m.text("\n$EndElements\n");
  return m.bytes();
}

void expectTwoTetrahedra(const GmshTetrahedra& read) {
  ASSERT_EQ(read.mesh.nodeCount(), 5);
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(read.mesh.nodes.row(i),
              Eigen::RowVector3d(kPoints[i][0], kPoints[i][1], kPoints[i][2]));
  ASSERT_EQ(read.mesh.elementCount(), 2);
  EXPECT_EQ(read.mesh.elements.row(0), Eigen::RowVector4i(1, 2, 0, 3));
  EXPECT_EQ(read.mesh.elements.row(1), Eigen::RowVector4i(2, 3, 0, 4));
  EXPECT_EQ(read.elementTags, (std::vector<long long>{7, 8}));
  EXPECT_EQ(read.skippedElements, 1);
}

TEST(GmshFormat, BinaryFilesInBothByteOrders) {
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big-endian" : "little-endian");
    expectTwoTetrahedra(parseGmshTetrahedra(binary22(big), "b22.msh"));
    expectTwoTetrahedra(parseGmshTetrahedra(binary41(big, 8), "b41.msh"));
    expectTwoTetrahedra(parseGmshTetrahedra(binary41(big, 4), "b41_4.msh"));
  }
}

// Cut short anywhere, a binary file is an error naming the file, never a
// crash or a mesh made of what was there; bytes flipped are an error or a
// mesh (the coordinates' bytes may flip to other numbers), never a crash.
TEST(GmshFormat, TruncatedOrDamagedBinaryFilesAreErrors) {
  const std::string dir = std::string(TETSKIN_SOURCE_DIR) + "/tests/data/gmsh/";
  std::ifstream file(dir + "sphere_coarse_v22_binary.msh", std::ios::binary);
  std::stringstream gmshWrote;
  gmshWrote << file.rdbuf();
  for (const std::string& whole : {binary22(false), binary41(true, 8), gmshWrote.str()}) {
    const std::size_t step = std::max<std::size_t>(1, whole.size() / 600);
    // (The last line end may go: a file ending in $EndElements is whole.)
    for (std::size_t cut = 0; cut + 1 < whole.size(); cut += step) {
      SCOPED_TRACE("cut at " + std::to_string(cut));
      try {
        parseGmshTetrahedra(whole.substr(0, cut), "cut.msh");
        ADD_FAILURE() << "no error";
      } catch (const Error& e) {
        EXPECT_EQ(e.file(), "cut.msh");
      }
    }
    for (std::size_t at = 0; at < whole.size(); at += step) {
      std::string damaged = whole;
      damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
      try {
        parseGmshTetrahedra(damaged, "damaged.msh");
      } catch (const Error& e) {
        EXPECT_EQ(e.file(), "damaged.msh");
      }
    }
  }
}

TEST(GmshFormat, BrokenBinaryFilesAreNamedByByte) {
  std::string b = binary22(false);
  std::string wrongOrder = b;
  wrongOrder[20] = 7;  // the byte-order check
  test::expectErrorAt([&] { parseGmshTetrahedra(wrongOrder, "b.msh"); }, "b.msh", 0,
                      "byte 20: the byte order check after the format line is not the integer 1");
  const std::size_t count = b.find("$Nodes\n5\n") + 7;
  const std::string hugeCount = b.substr(0, count) + "5000" + b.substr(count + 1);
  test::expectErrorAt([&] { parseGmshTetrahedra(hugeCount, "b.msh"); }, "b.msh", 0,
                      "node count 5000 is more than the rest of the file can hold");
  test::expectErrorAt([&] { parseGmshTetrahedra("$MeshFormat\n4.1 1 6\n", "b.msh"); }, "b.msh", 2,
                      "data size 6 is neither 4 nor 8 bytes");
}

}  // namespace
}  // namespace tetskin
