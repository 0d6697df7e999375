// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/TetGenFormat.h"

namespace tetskin {
namespace {

using namespace std::string_view_literals;

template <typename Parse>
void expectError(Parse parse, std::string_view content, long line, const std::string& what) {
  test::expectErrorAt([&] { parse(content, "bad.file"); }, "bad.file", line, what);
}

const auto node = [](std::string_view c, const std::string& n) { return parseNode(c, n); };
const auto ele = [](std::string_view c, const std::string& n) { return parseEle(c, n); };
const auto face = [](std::string_view c, const std::string& n) { return parseFace(c, n); };
const auto poly = [](std::string_view c, const std::string& n) { return parsePoly(c, n); };

TEST(TetGenFormat, NodeFileOneBasedWithAttributesAndMarkers) {
  const NodeFile f = parseNode(
      "# comment line\n"
      "3 3 2 1\n"
      "1 0 0 0  0.5 7  1 # trailing comment\n"
      "2 1 0 0  0.25 8 0\n"
      "3 0 1 0  0.125 9 2\n",
      "n.node");
  EXPECT_EQ(f.firstIndex, 1);
  ASSERT_EQ(f.points.rows(), 3);
  EXPECT_EQ(f.points.row(1), Eigen::RowVector3d(1, 0, 0));
  ASSERT_EQ(f.attributes.cols(), 2);
  EXPECT_EQ(f.attributes(2, 0), 0.125);
  EXPECT_EQ(f.markers, (std::vector<int>{1, 0, 2}));
}

TEST(TetGenFormat, NodeFileZeroBasedMinimalHeader) {
  const NodeFile f = parseNode("2 3 0 0\n0 1 2 3\n1 4 5 6", "n.node");
  EXPECT_EQ(f.firstIndex, 0);
  EXPECT_EQ(f.points(1, 2), 6.0);
  EXPECT_TRUE(f.markers.empty());
  EXPECT_EQ(f.attributes.cols(), 0);
}

TEST(TetGenFormat, EleFileIndicesBecomeZeroBased) {
  const EleFile f = parseEle("2 4 1\n1 1 2 3 4 5\n2 2 3 4 5 6\n", "e.ele");
  EXPECT_EQ(f.firstIndex, 1);
  EXPECT_EQ(f.elements.row(0), Eigen::RowVector4i(0, 1, 2, 3));
  EXPECT_EQ(f.attributes(1, 0), 6.0);
  const EleFile quadratic = parseEle("1 10 0\n0 0 1 2 3 4 5 6 7 8 9\n", "q.ele");
  EXPECT_EQ(quadratic.elements.cols(), 10);
  EXPECT_EQ(quadratic.corners().row(0), Eigen::RowVector4i(0, 1, 2, 3));
}

TEST(TetGenFormat, FaceFileWithMarkers) {
  const FaceFile f = parseFace("2 1\n0 0 1 2 -1\n1 1 2 3 5\n", "f.face");
  EXPECT_EQ(f.faces.row(1), Eigen::RowVector3i(1, 2, 3));
  EXPECT_EQ(f.markers, (std::vector<int>{-1, 5}));
}

constexpr std::string_view kCubePoly =
    "# unit cube, 1-based\n"
    "8 3 0 1\n"
    "1 0 0 0 1\n2 1 0 0 1\n3 1 1 0 1\n4 0 1 0 1\n"
    "5 0 0 1 1\n6 1 0 1 1\n7 1 1 1 1\n8 0 1 1 1\n"
    "6 1\n"
    "1 0 1\n4 1 4 3 2\n"
    "1 0 2\n4 5 6 7 8\n"
    "1 0 3\n4 1 2 6 5\n"
    "1 0 4\n4 2 3 7 6\n"
    "1 0 5\n4 3 4 8 7\n"
    "2 1 6\n4 4 1 5 8\n3 1 5 8\n1 0 0.5 0.5\n"
    "1\n1 0.5 0.5 0.5\n"
    "1\n1 0.25 0.25 0.25 7 0.01\n";

TEST(TetGenFormat, PolyFileAllSections) {
  const PolyFile p = parsePoly(kCubePoly, "cube.poly");
  EXPECT_EQ(p.nodes.firstIndex, 1);
  EXPECT_EQ(p.nodes.points.rows(), 8);
  ASSERT_EQ(p.facets.size(), 6u);
  EXPECT_TRUE(p.facetMarkers);
  EXPECT_EQ(p.facets[0].polygons[0], (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(p.facets[5].marker, 6);
  EXPECT_EQ(p.facets[5].polygons.size(), 2u);
  EXPECT_EQ(p.facets[5].holes.rows(), 1);
  EXPECT_EQ(p.holes.rows(), 1);
  ASSERT_EQ(p.regions.size(), 1u);
  EXPECT_EQ(p.regions[0].attribute, 7.0);
  EXPECT_EQ(p.regions[0].maxVolume, 0.01);
}

TEST(TetGenFormat, RoundTripsAreExact) {
  test::ScratchDir dir;
  const PolyFile p = parsePoly(kCubePoly, "cube.poly");
  writePoly(dir / "c.poly", p);
  const PolyFile back = readPoly(dir / "c.poly");
  EXPECT_EQ(back.nodes.points, p.nodes.points);
  EXPECT_EQ(back.nodes.markers, p.nodes.markers);
  EXPECT_EQ(back.nodes.firstIndex, 1);
  ASSERT_EQ(back.facets.size(), p.facets.size());
  for (std::size_t i = 0; i < p.facets.size(); ++i) {
    EXPECT_EQ(back.facets[i].polygons, p.facets[i].polygons);
    EXPECT_EQ(back.facets[i].marker, p.facets[i].marker);
    EXPECT_EQ(back.facets[i].holes, p.facets[i].holes);
  }
  EXPECT_EQ(back.holes, p.holes);
  EXPECT_EQ(back.regions[0].point, p.regions[0].point);
  EXPECT_EQ(back.regions[0].maxVolume, p.regions[0].maxVolume);

  NodeFile n;
  n.points.resize(2, 3);
  // (Coordinates stay within kMaxCoordinate; attributes may be any double.)
  n.points << 0.1, 1.0 / 3.0, -7e-300, 9.87654321012345e29, 2, 3;
  n.attributes.resize(2, 1);
  n.attributes << 4.5, 1e300;
  n.markers = {3, 4};
  writeNode(dir / "a.node", n);
  const NodeFile nb = readNode(dir / "a.node");
  EXPECT_EQ(nb.points, n.points);
  EXPECT_EQ(nb.attributes, n.attributes);
  EXPECT_EQ(nb.markers, n.markers);

  EleFile e;
  e.firstIndex = 1;
  e.elements.resize(1, 4);
  e.elements << 0, 1, 1, 0;
  e.attributes = Eigen::MatrixXd::Constant(1, 1, 2.0);
  writeEle(dir / "a.ele", e);
  const EleFile eb = readEle(dir / "a.ele");
  EXPECT_EQ(eb.elements, e.elements);
  EXPECT_EQ(eb.attributes, e.attributes);
  EXPECT_EQ(eb.firstIndex, 1);

  FaceFile f;
  f.faces.resize(1, 3);
  f.faces << 2, 1, 0;
  f.markers = {9};
  writeFace(dir / "a.face", f);
  const FaceFile fb = readFace(dir / "a.face");
  EXPECT_EQ(fb.faces, f.faces);
  EXPECT_EQ(fb.markers, f.markers);
}

TEST(TetGenFormat, PolyWithSeparateNodeFile) {
  test::ScratchDir dir;
  dir.write("s.node", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n");
  dir.write("s.poly", "0 3 0 0\n1 0\n1\n3 1 2 3\n");
  const PolyFile p = readPoly(dir / "s.poly");
  EXPECT_TRUE(p.nodesInSeparateFile);
  EXPECT_EQ(p.nodes.points.rows(), 3);
  EXPECT_EQ(p.facets[0].polygons[0], (std::vector<int>{0, 1, 2}));
}

TEST(TetGenFormat, ReadTetMeshChecksNodeIndices) {
  test::ScratchDir dir;
  dir.write("m.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  dir.write("m.ele", "1 4 0\n0 0 1 2 3\n");
  const TetMesh m = readTetMesh(dir / "m.node", dir / "m.ele");
  EXPECT_EQ(m.elementCount(), 1);
  dir.write("bad.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  dir.write("bad.ele", "1 4 0\n0 0 1 2 4\n");
  try {
    readTetMesh(dir / "bad.node", dir / "bad.ele");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.ele: element 0 refers to node 4"), std::string::npos)
        << e.what();
  }
}

TEST(TetGenFormat, MalformedInputNamesFileAndLine) {
  expectError(node, "", 0, "unexpected end of file");
  expectError(node, "# nothing\n", 1, "unexpected end of file");
  expectError(node, "3 3 0 0\n0 0 0 0\n1 1 0 0\n", 3, "unexpected end of file");  // truncated
  expectError(node, "1 3 0 0\n0 0 0 0\n1 1 0 0\n", 3, "unexpected data after");   // wrong count
  expectError(node, "2 3 0 0\n0 0 0 0\n2 1 0 0\n", 3, "should be 1");             // numbering
  expectError(node, "1 3 0 0\n5 0 0 0\n", 2, "numbered 0 or 1");
  expectError(node, "1 3 0 0\n0 0 nan 0\n", 2, "not a finite number");
  expectError(node, "1 3 0 0\n0 0 1e31 0\n", 2, "node has a coordinate of magnitude 1e+31");
  expectError(node, "1 3 0 0\n0 0 x 0\n", 2, "'x' is not a number");
  expectError(node, "1 3 0 0\n0 0 0\n", 2, "expected 4 values");
  expectError(node, "1 2 0 0\n0 0 0\n", 1, "dimension must be 3");
  expectError(node, "99999999999999 3 0 0\n0 0 0 0\n", 1, "more than the rest of the file");
  expectError(node, "-1 3 0 0\n", 1, "negative");
  expectError(node, "1 3 0 0\n0 0\x00 0 0\n"sv, 2, "binary data");
  expectError(ele, "1 4 0\n0 0 1 2\n", 2, "expected 5 values");
  expectError(ele, "1 5 0\n0 0 1 2 3 4\n", 1, "4 or 10");
  expectError(ele, "1 4 0\n1 0 1 2 3\n", 2, "below the first index");
  expectError(ele, "2 4 0\n0 0 1 2 3\n", 2, "unexpected end of file");
  expectError(face, "1 0\n0 0 1\n", 2, "expected 4 to 6 values");
  expectError(poly, "0 3 0 0\n1 0\n1\n4 1 2 3\n", 4, "declares 4 corners but lists 3");
  expectError(poly, "0 3 0 0\n2 0\n1\n3 1 2 3\n", 4, "unexpected end of file");
  // A facet naming a node the file does not list (found by fuzz_tetgen).
  expectError(poly, "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1\n3 1 13 2\n", 7,
              "node index 13 names no node: the file lists 3 from 1");
}

TEST(TetGenFormat, BinaryGarbageIsAClearError) {
  std::string garbage = "4 3 0 0\n";
  for (int i = 0; i < 2048; ++i) garbage.push_back(static_cast<char>(1 + (i * 7919) % 255));
  EXPECT_THROW(parseNode(garbage, "g.node"), Error);
  EXPECT_THROW(parseEle(garbage, "g.ele"), Error);
  EXPECT_THROW(parsePoly(garbage, "g.poly"), Error);
}

}  // namespace
}  // namespace tetskin
