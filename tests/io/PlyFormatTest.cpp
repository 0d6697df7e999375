// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/PlyFormat.h"

namespace tetskin {
namespace {

void expectPlyError(std::string_view content, long line, const std::string& what) {
  test::expectErrorAt([&] { parsePly(content, "bad.ply"); }, "bad.ply", line, what);
}

// A unit quad with normals, texture coordinates (as s, t), a colour the
// reader skips, and an element it does not know.
constexpr std::string_view kAsciiQuad =
    "ply\n"
    "format ascii 1.0\n"
    "comment a unit quad\n"
    "obj_info from a test\n"
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property uchar red\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property float s\nproperty float t\n"
    "element face 1\n"
    "property list uchar int vertex_indices\n"
    "element edge 1\n"
    "property int vertex1\nproperty int vertex2\n"
    "end_header\n"
    "0 0 0 255 0 0 1 0 0\n"
    "1 0 0 255 0 0 1 1 0\n"
    "1 1 0 255 0 0 1 1 1\n"
    "0 1 0 255 0 0 1 0 1\n"
    "4 0 1 2 3\n"
    "0 1\n";

void expectQuad(const SurfaceMesh& m) {
  EXPECT_EQ(m.vertexCount(), 4);
  ASSERT_EQ(m.triangleCount(), 2);
  EXPECT_EQ(m.triangles.row(0), Eigen::RowVector3i(0, 1, 2));  // a fan
  EXPECT_EQ(m.triangles.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.positions.row(2), Eigen::RowVector3d(1, 1, 0));
  ASSERT_TRUE(m.hasNormals());
  EXPECT_EQ(m.normals.row(3), Eigen::RowVector3d(0, 0, 1));
  ASSERT_TRUE(m.hasTexcoords());
  EXPECT_EQ(m.texcoords.row(1), Eigen::RowVector2d(1, 0));
}

TEST(PlyFormat, AsciiQuadWithAttributesAndUnknownElements) {
  expectQuad(parsePly(kAsciiQuad, "quad.ply"));
  // CRLF line ends read the same.
  std::string crlf;
  for (char c : kAsciiQuad) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expectQuad(parsePly(crlf, "quad.ply"));
}

// The quad in binary, with types of every width: x float, y double, z short,
// a uchar colour, normals float, u v double; the face list with a ushort
// count and uint indices.
std::string binaryQuad(bool bigEndian) {
  std::string out =
      std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\nelement vertex 4\nproperty float x\nproperty double y\nproperty short z\n"
      "property uchar red\nproperty float nx\nproperty float ny\nproperty float nz\n"
      "property double u\nproperty double v\n"
      "element face 1\nproperty list ushort uint vertex_indices\nend_header\n";
  auto put = [&](auto value) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    if (bigEndian != (std::endian::native == std::endian::big))
      std::reverse(bytes, bytes + sizeof value);
    out.append(bytes, sizeof value);
  };
  const double xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& p : xy) {
    put(static_cast<float>(p[0]));
    put(p[1]);
    put(std::int16_t{0});
    put(std::uint8_t{200});
    put(0.0f), put(0.0f), put(1.0f);
    put(p[0]), put(p[1]);
  }
  put(std::uint16_t{4});
  for (std::uint32_t i = 0; i < 4; ++i) put(i);
  return out;
}

TEST(PlyFormat, ANonConvexFaceIsClippedOnceItsVerticesAreRead) {
  // The L of ObjFormat's test, its face element before its vertex element
  // (which PLY allows): the face is triangulated with the positions in hand.
  const SurfaceMesh m = parsePly(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 6\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
      "6 0 1 2 3 4 5\n0 2 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n",
      "l.ply");
  ASSERT_EQ(m.triangleCount(), 4);
  double total = 0;
  for (Index t = 0; t < m.triangleCount(); ++t) {
    const Eigen::Vector3d a = m.positions.row(m.triangles(t, 0)).transpose();
    const Eigen::Vector3d b = m.positions.row(m.triangles(t, 1)).transpose();
    const Eigen::Vector3d c = m.positions.row(m.triangles(t, 2)).transpose();
    const double area = (b - a).cross(c - a).z() / 2;
    EXPECT_GT(area, 0) << "triangle " << t;
    total += area;
  }
  EXPECT_DOUBLE_EQ(total, 3);
}

TEST(PlyFormat, BinaryInEitherByteOrderReadsAsTheAsciiFile) {
  expectQuad(parsePly(binaryQuad(false), "quad_le.ply"));
  expectQuad(parsePly(binaryQuad(true), "quad_be.ply"));
}

TEST(PlyFormat, WrittenFilesReadBackExactly) {
  test::ScratchDir dir;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> any(-3, 3);
  SurfaceMesh m;
  m.positions = Points3::NullaryExpr(50, 3, [&] { return any(random); });
  m.normals = Points3::NullaryExpr(50, 3, [&] { return any(random); });
  m.texcoords = Points2::NullaryExpr(50, 2, [&] { return any(random); });
  m.triangles.resize(40, 3);
  for (int t = 0; t < 40; ++t) m.triangles.row(t) << t, t + 5, t + 9;
  writePly(dir / "m.ply", m);
  const SurfaceMesh back = readPly(dir / "m.ply");
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.normals, m.normals);
  EXPECT_EQ(back.texcoords, m.texcoords);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(test::readText(dir / "m.ply").rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  // Without attributes none come back.
  m.normals.resize(0, 3);
  m.texcoords.resize(0, 2);
  writePly(dir / "plain.ply", m);
  const SurfaceMesh plain = readPly(dir / "plain.ply");
  EXPECT_FALSE(plain.hasNormals());
  EXPECT_FALSE(plain.hasTexcoords());
  EXPECT_EQ(plain.positions, m.positions);
  // A mesh that is not valid is refused before anything is written.
  m.triangles(3, 1) = 50;
  EXPECT_THROW(writePly(dir / "broken.ply", m), Error);
  EXPECT_EQ(dir.listing(), "m.ply\nplain.ply\n");
}

const std::string kHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyFormat, MalformedHeadersAreNamedWithTheirLine) {
  expectPlyError("plx\n", 1, "not a PLY file");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 3\n", 3, "no end_header");
  expectPlyError("ply\nformat utf16 1.0\nend_header\n", 2, "unknown PLY format 'utf16'");
  expectPlyError("ply\nelement vertex 3\nend_header\n", 3, "no format line");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\n", 4,
                 "unknown PLY type 'quad'");
  expectPlyError("ply\nformat ascii 1.0\nproperty float x\n", 3, "a property before any element");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex -3\n", 3, "is negative");
  expectPlyError("ply\nformat ascii 1.0\nCreated by hand\nend_header\n", 3,
                 "unknown PLY header line 'Created'");
  expectPlyError(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n",
      3, "vertices have no 'z' property");
  expectPlyError(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n",
      0, "no face element (a point cloud");
  expectPlyError(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n",
      7, "must hold integers");
  expectPlyError(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty uchar flags\nend_header\n",
      7, "faces have no vertex_indices list");
}

TEST(PlyFormat, MalformedAsciiBodiesAreNamedWithTheirLine) {
  // The body starts on line 10.
  expectPlyError(kHeader + "0 0 0\n1 0 abc\n0 1 0\n3 0 1 2\n", 11,
                 "vertex z 'abc' is not a number");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n", 12, "is not a finite number");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 1e31\n3 0 1 2\n", 12, "vertex 2 has a coordinate");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, "a face needs at least 3 vertices");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13,
                 "vertex index 3 is out of range (3 vertices)");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 13,
                 "vertex index -1 is out of range");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", 13,
                 "list 'vertex_indices' of 3 items is more than the rest of the file can hold "
                 "(truncated");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n    \n", 13,
                 "the file ends inside face 0 (truncated file?)");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n", 14, "data after the last element");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", 13, "is not an integer");
  // A count the rest of the file cannot hold is refused before it is allocated.
  std::string huge = kHeader;
  huge.replace(huge.find("vertex 3"), 8, "vertex 4000000000");
  expectPlyError(huge + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 3,
                 "is more than the rest of the file can hold");
  expectPlyError(kHeader + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", 13,
                 "list 'vertex_indices' of 200 items is more than the rest of the file can hold");
  // An empty face element is a surface without triangles.
  std::string none = kHeader;
  none.replace(none.find("face 1"), 6, "face 0");
  expectPlyError(none + "0 0 0\n1 0 0\n0 1 0\n", 0, "contains no triangles");
}

TEST(PlyFormat, MalformedBinaryBodiesNameTheElement) {
  const std::string quad = binaryQuad(false);
  // Cut inside the face's indices: its list no longer fits.
  expectPlyError(quad.substr(0, quad.size() - 3), 0,
                 "face 0: list 'vertex_indices' of 4 items is more than the rest of the file can "
                 "hold (truncated");
  // Cut inside the third vertex: the vertex count no longer fits (its line).
  const std::size_t body = quad.find("end_header\n") + 11;
  const std::size_t vertexBytes = 4 + 8 + 2 + 1 + 12 + 16;
  expectPlyError(quad.substr(0, body + 2 * vertexBytes + 5), 3,
                 "element 'vertex' count 4 is more than the rest of the file can hold (truncated");
  // Cut inside the face's list count: what is left fits no value.
  expectPlyError(quad.substr(0, body + 4 * vertexBytes + 1), 13,
                 "element 'face' count 1 is more than the rest of the file can hold");
  // A NaN coordinate (y of vertex 1, a double).
  std::string nan = quad;
  const double bad = std::nan("");
  std::memcpy(nan.data() + body + vertexBytes + 4, &bad, 8);
  expectPlyError(nan, 0, "vertex 1 has a non-finite coordinate");
  // An absurd list count (ushort 65535).
  std::string list = quad;
  list[body + 4 * vertexBytes] = '\xff';
  list[body + 4 * vertexBytes + 1] = '\xff';
  expectPlyError(list, 0, "face 0: list 'vertex_indices' of 65535 items is more than");
  // Cut inside a value whose element seemed to fit: the list count of a
  // face when the face element's minimum (its count alone) still fits.
  std::string twoFaces = quad;
  twoFaces.replace(twoFaces.find("face 1"), 6, "face 2");
  expectPlyError(twoFaces + "\x03", 0, "the file ends inside face 1 (truncated file?)");
  // Bytes left over: the header's counts do not describe the data.
  expectPlyError(quad + "junk", 0, "4 bytes after the last element");
}

// Random damage to valid files (bytes changed, cut short, bytes inserted)
// must end in a mesh whose indices are in range or in an Error naming the
// file: never a crash, a hang or a huge allocation (CI runs this under ASan).
TEST(PlyFormat, DamagedFilesNeverCrash) {
  std::mt19937 random(2024);
  int read = 0, refused = 0;
  for (const std::string& original :
       {binaryQuad(false), binaryQuad(true), std::string(kAsciiQuad)}) {
    for (int trial = 0; trial < 400; ++trial) {
      std::string damaged = original;
      const auto at = [&](std::size_t size) {
        return std::uniform_int_distribution<std::size_t>(0, size - 1)(random);
      };
      switch (trial % 3) {
        case 0:
          for (int k = 0; k < 1 + trial % 7; ++k)
            damaged[at(damaged.size())] = static_cast<char>(random());
          break;
        case 1:
          damaged.resize(at(damaged.size()));
          break;
        default:
          damaged.insert(at(damaged.size()),
                         std::string(1 + trial % 5, static_cast<char>(random())));
      }
      try {
        const SurfaceMesh m = parsePly(damaged, "damaged.ply");
        EXPECT_NO_THROW(validateSurface(m, "damaged.ply"));
        ++read;
      } catch (const Error& e) {
        EXPECT_EQ(e.file(), "damaged.ply");
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 600);  // most damage is caught
  EXPECT_EQ(read + refused, 1200);
}

}  // namespace
}  // namespace tetskin
