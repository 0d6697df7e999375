// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/TetGenFormat.h"

#include <array>

#include "NumberFormat.h"
#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

using detail::TextLines;

// Reads the next line of a section; a file that ends early is truncated.
void nextLine(TextLines& lines, const char* expected) {
  if (!lines.next())
    throw Error(lines.sourceName(), lines.lineNumber(),
                std::string("unexpected end of file, expected ") + expected + " (truncated file?)");
}

int toInt(const TextLines& lines, std::string_view token, const char* what) {
  const long long value = lines.toInteger(token, what);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    lines.fail(std::string(what) + " " + std::string(token) + " is out of range");
  return static_cast<int>(value);
}

// Checks the item number of item `i` and returns the file's index base.
int checkItemNumber(const TextLines& lines, int i, int firstIndex, const char* what) {
  const int number = toInt(lines, lines[0], what);
  if (i == 0) {
    if (number != 0 && number != 1)
      lines.fail(std::string("the first ") + what + " must be numbered 0 or 1, found " +
                 std::to_string(number));
    return number;
  }
  if (number != firstIndex + i)
    lines.fail(std::string(what) + " number " + std::to_string(number) + " should be " +
               std::to_string(firstIndex + i) + " (numbers must be consecutive)");
  return firstIndex;
}

int toNodeIndex(const TextLines& lines, std::string_view token, int firstIndex) {
  const int id = toInt(lines, token, "node index") - firstIndex;
  if (id < 0)
    lines.fail("node index " + std::string(token) + " is below the first index " +
               std::to_string(firstIndex));
  return id;
}

// The point list of a .node file or of the first section of a .poly file,
// starting at its header line (already current).
NodeFile parsePointSection(TextLines& lines) {
  lines.expectTokens(1, 4, "node header (<count> <dimension> <attributes> <markers>)");
  const long long count = lines.toInteger(lines[0], "node count");
  const int dimension = lines.size() > 1 ? toInt(lines, lines[1], "dimension") : 3;
  const int attributeCount = lines.size() > 2 ? toInt(lines, lines[2], "attribute count") : 0;
  const int markerFlag = lines.size() > 3 ? toInt(lines, lines[3], "boundary marker flag") : 0;
  if (dimension != 3 && !(count == 0 && dimension == 0))
    lines.fail("dimension must be 3, found " + std::to_string(dimension));
  if (attributeCount < 0 || attributeCount > 1000)
    lines.fail("attribute count " + std::to_string(attributeCount) + " is not plausible");
  if (markerFlag != 0 && markerFlag != 1)
    lines.fail("boundary marker flag must be 0 or 1, found " + std::to_string(markerFlag));
  lines.checkCount(count, 2, "node count");
  NodeFile file;
  const Index n = static_cast<Index>(count);
  file.points.resize(n, 3);
  file.attributes.resize(n, attributeCount);
  if (markerFlag) file.markers.resize(static_cast<std::size_t>(n));
  const std::size_t columns = 4 + static_cast<std::size_t>(attributeCount + markerFlag);
  for (Index i = 0; i < n; ++i) {
    nextLine(lines, "a node");
    lines.expectTokens(columns, columns, "node");
    file.firstIndex = checkItemNumber(lines, static_cast<int>(i), file.firstIndex, "node");
    const std::array<double, 3> point = lines.toPoint(1, "node");
    for (int k = 0; k < 3; ++k) file.points(i, k) = point[static_cast<std::size_t>(k)];
    for (int a = 0; a < attributeCount; ++a)
      file.attributes(i, a) = lines.toDouble(lines[4 + a], "attribute");
    if (markerFlag)
      file.markers[static_cast<std::size_t>(i)] =
          toInt(lines, lines[4 + attributeCount], "boundary marker");
  }
  return file;
}

void expectEnd(TextLines& lines) {
  if (lines.next()) lines.fail("unexpected data after the last item");
}

// `count` lines "INDEX X Y Z", each a point inside a hole (of the whole
// domain or of one facet), into `holes`.
void parseHolePoints(TextLines& lines, long long count, const char* nextExpected, const char* what,
                     Points3& holes) {
  holes.resize(static_cast<Index>(count), 3);
  for (Index h = 0; h < holes.rows(); ++h) {
    nextLine(lines, nextExpected);
    lines.expectTokens(4, 4, what);
    for (int k = 0; k < 3; ++k) holes(h, k) = lines.toDouble(lines[1 + k], "coordinate");
  }
}

}  // namespace

NodeFile parseNode(std::string_view content, const std::string& sourceName) {
  TextLines lines(content, sourceName);
  nextLine(lines, "the node header");
  NodeFile file = parsePointSection(lines);
  expectEnd(lines);
  return file;
}

EleFile parseEle(std::string_view content, const std::string& sourceName) {
  TextLines lines(content, sourceName);
  nextLine(lines, "the element header");
  lines.expectTokens(1, 3, "element header (<count> <nodes per element> <attributes>)");
  const long long count = lines.toInteger(lines[0], "element count");
  const int perElement = lines.size() > 1 ? toInt(lines, lines[1], "nodes per element") : 4;
  const int attributeCount = lines.size() > 2 ? toInt(lines, lines[2], "attribute count") : 0;
  if (perElement != 4 && perElement != 10)
    lines.fail("nodes per element must be 4 or 10, found " + std::to_string(perElement));
  if (attributeCount < 0 || attributeCount > 1000)
    lines.fail("attribute count " + std::to_string(attributeCount) + " is not plausible");
  lines.checkCount(count, 2, "element count");
  EleFile file;
  const Index n = static_cast<Index>(count);
  file.elements.resize(n, perElement);
  file.attributes.resize(n, attributeCount);
  const std::size_t columns = 1 + static_cast<std::size_t>(perElement + attributeCount);
  for (Index i = 0; i < n; ++i) {
    nextLine(lines, "an element");
    lines.expectTokens(columns, columns, "element");
    file.firstIndex = checkItemNumber(lines, static_cast<int>(i), file.firstIndex, "element");
    for (int k = 0; k < perElement; ++k)
      file.elements(i, k) = toNodeIndex(lines, lines[1 + k], file.firstIndex);
    for (int a = 0; a < attributeCount; ++a)
      file.attributes(i, a) = lines.toDouble(lines[1 + perElement + a], "attribute");
  }
  expectEnd(lines);
  return file;
}

FaceFile parseFace(std::string_view content, const std::string& sourceName) {
  TextLines lines(content, sourceName);
  nextLine(lines, "the face header");
  lines.expectTokens(1, 2, "face header (<count> <markers>)");
  const long long count = lines.toInteger(lines[0], "face count");
  const int markerFlag = lines.size() > 1 ? toInt(lines, lines[1], "boundary marker flag") : 0;
  if (markerFlag != 0 && markerFlag != 1)
    lines.fail("boundary marker flag must be 0 or 1, found " + std::to_string(markerFlag));
  lines.checkCount(count, 2, "face count");
  FaceFile file;
  const Index n = static_cast<Index>(count);
  file.faces.resize(n, 3);
  if (markerFlag) file.markers.resize(static_cast<std::size_t>(n));
  // TetGen may append the two adjacent tetrahedra (-nn); they are not kept.
  const std::size_t columns = 4 + static_cast<std::size_t>(markerFlag);
  for (Index i = 0; i < n; ++i) {
    nextLine(lines, "a face");
    lines.expectTokens(columns, columns + 2, "face");
    file.firstIndex = checkItemNumber(lines, static_cast<int>(i), file.firstIndex, "face");
    for (int k = 0; k < 3; ++k)
      file.faces(i, k) = toNodeIndex(lines, lines[1 + k], file.firstIndex);
    if (markerFlag)
      file.markers[static_cast<std::size_t>(i)] = toInt(lines, lines[4], "boundary marker");
  }
  expectEnd(lines);
  return file;
}

PolyFile parsePoly(std::string_view content, const std::string& sourceName, int nodeFirstIndex) {
  TextLines lines(content, sourceName);
  PolyFile poly;
  nextLine(lines, "the node header");
  poly.nodes = parsePointSection(lines);
  poly.nodesInSeparateFile = poly.nodes.points.rows() == 0;
  const int base = poly.nodesInSeparateFile ? std::max(nodeFirstIndex, 0) : poly.nodes.firstIndex;

  nextLine(lines, "the facet header");
  lines.expectTokens(1, 2, "facet header (<count> <markers>)");
  const long long facetCount = lines.toInteger(lines[0], "facet count");
  const int markerFlag = lines.size() > 1 ? toInt(lines, lines[1], "boundary marker flag") : 0;
  if (markerFlag != 0 && markerFlag != 1)
    lines.fail("boundary marker flag must be 0 or 1, found " + std::to_string(markerFlag));
  lines.checkCount(facetCount, 2, "facet count");
  poly.facetMarkers = markerFlag == 1;
  poly.facets.resize(static_cast<std::size_t>(facetCount));
  for (PolyFacet& facet : poly.facets) {
    nextLine(lines, "a facet");
    lines.expectTokens(1, 3, "facet (<polygons> [holes] [marker])");
    const long long polygonCount = lines.toInteger(lines[0], "polygon count");
    const long long holeCount = lines.size() > 1 ? lines.toInteger(lines[1], "hole count") : 0;
    if (lines.size() > 2) facet.marker = toInt(lines, lines[2], "boundary marker");
    lines.checkCount(polygonCount, 2, "polygon count");
    lines.checkCount(holeCount, 2, "hole count");
    for (long long p = 0; p < polygonCount; ++p) {
      nextLine(lines, "a polygon");
      const long long corners = lines.toInteger(lines[0], "corner count");
      if (corners < 1 || static_cast<std::size_t>(corners) + 1 != lines.size())
        lines.fail("polygon declares " + std::to_string(corners) + " corners but lists " +
                   std::to_string(lines.size() - 1));
      std::vector<int>& polygon = facet.polygons.emplace_back();
      for (std::size_t k = 1; k < lines.size(); ++k) {
        const int id = toNodeIndex(lines, lines[k], base);
        // (A .poly whose points are in a separate .node file is checked
        // against it by whoever pairs the two.)
        if (!poly.nodesInSeparateFile && id >= poly.nodes.points.rows())
          lines.fail("node index " + std::string(lines[k]) + " names no node: the file lists " +
                     std::to_string(poly.nodes.points.rows()) + " from " + std::to_string(base));
        polygon.push_back(id);
      }
    }
    parseHolePoints(lines, holeCount, "a facet hole", "facet hole", facet.holes);
  }

  // The hole and region lists are optional at the end of the file.
  if (!lines.next()) return poly;
  lines.expectTokens(1, 1, "hole count");
  const long long holeCount = lines.toInteger(lines[0], "hole count");
  lines.checkCount(holeCount, 2, "hole count");
  parseHolePoints(lines, holeCount, "a hole", "hole", poly.holes);
  if (!lines.next()) return poly;
  lines.expectTokens(1, 1, "region count");
  const long long regionCount = lines.toInteger(lines[0], "region count");
  lines.checkCount(regionCount, 2, "region count");
  poly.regions.resize(static_cast<std::size_t>(regionCount));
  for (PolyRegion& region : poly.regions) {
    nextLine(lines, "a region");
    lines.expectTokens(5, 6, "region");
    for (int k = 0; k < 3; ++k) region.point[k] = lines.toDouble(lines[1 + k], "coordinate");
    region.attribute = lines.toDouble(lines[4], "region attribute");
    if (lines.size() > 5) region.maxVolume = lines.toDouble(lines[5], "volume constraint");
  }
  expectEnd(lines);
  return poly;
}

NodeFile readNode(const std::filesystem::path& path) {
  return parseNode(detail::readWholeFile(path), path.string());
}
EleFile readEle(const std::filesystem::path& path) {
  return parseEle(detail::readWholeFile(path), path.string());
}
FaceFile readFace(const std::filesystem::path& path) {
  return parseFace(detail::readWholeFile(path), path.string());
}

NodeElePaths nodeElePair(const std::filesystem::path& either) {
  NodeElePaths pair{either, either};
  pair.node.replace_extension(".node");
  pair.ele.replace_extension(".ele");
  return pair;
}

PolyFile readPoly(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  PolyFile poly = parsePoly(content, path.string());
  if (!poly.nodesInSeparateFile) return poly;
  std::filesystem::path nodePath = path;
  nodePath.replace_extension(".node");
  NodeFile nodes = readNode(nodePath);
  if (nodes.firstIndex != 0) poly = parsePoly(content, path.string(), nodes.firstIndex);
  poly.nodes = std::move(nodes);
  return poly;
}

namespace {

template <typename Matrix>
void writeRowValues(std::ostream& out, const Matrix& m, Index row) {
  for (Index k = 0; k < m.cols(); ++k) {
    out << ' ';
    detail::writeDouble(out, static_cast<double>(m(row, k)));
  }
}

void writePointSection(std::ostream& out, const NodeFile& file) {
  const bool markers = !file.markers.empty();
  out << file.points.rows() << " 3 " << file.attributes.cols() << ' ' << (markers ? 1 : 0) << '\n';
  for (Index i = 0; i < file.points.rows(); ++i) {
    out << i + file.firstIndex;
    writeRowValues(out, file.points, i);
    if (file.attributes.rows() == file.points.rows()) writeRowValues(out, file.attributes, i);
    if (markers) out << ' ' << file.markers[static_cast<std::size_t>(i)];
    out << '\n';
  }
}

}  // namespace

void writeNode(const std::filesystem::path& path, const NodeFile& file) {
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "# TetSkin .node: <count> <dimension> <attributes> <markers>\n";
    writePointSection(out, file);
  });
}

void writeEle(const std::filesystem::path& path, const EleFile& file) {
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "# TetSkin .ele: <count> <nodes per element> <attributes>\n";
    out << file.elements.rows() << ' ' << file.elements.cols() << ' ' << file.attributes.cols()
        << '\n';
    for (Index i = 0; i < file.elements.rows(); ++i) {
      out << i + file.firstIndex;
      for (Index k = 0; k < file.elements.cols(); ++k)
        out << ' ' << file.elements(i, k) + file.firstIndex;
      if (file.attributes.rows() == file.elements.rows()) writeRowValues(out, file.attributes, i);
      out << '\n';
    }
  });
}

void writeFace(const std::filesystem::path& path, const FaceFile& file) {
  writeTextAtomically(path, [&](std::ostream& out) {
    const bool markers = !file.markers.empty();
    out << "# TetSkin .face: <count> <markers>\n";
    out << file.faces.rows() << ' ' << (markers ? 1 : 0) << '\n';
    for (Index i = 0; i < file.faces.rows(); ++i) {
      out << i + file.firstIndex;
      for (int k = 0; k < 3; ++k) out << ' ' << file.faces(i, k) + file.firstIndex;
      if (markers) out << ' ' << file.markers[static_cast<std::size_t>(i)];
      out << '\n';
    }
  });
}

void writePoly(const std::filesystem::path& path, const PolyFile& file) {
  writeTextAtomically(path, [&](std::ostream& out) {
    const int base = file.nodes.firstIndex;
    out << "# TetSkin .poly\n# part 1: nodes\n";
    if (file.nodesInSeparateFile)
      out << "0 3 0 0\n";
    else
      writePointSection(out, file.nodes);
    out << "# part 2: facets\n" << file.facets.size() << ' ' << (file.facetMarkers ? 1 : 0) << '\n';
    for (const PolyFacet& facet : file.facets) {
      out << facet.polygons.size() << ' ' << facet.holes.rows();
      if (file.facetMarkers) out << ' ' << facet.marker;
      out << '\n';
      for (const auto& polygon : facet.polygons) {
        out << polygon.size();
        for (int id : polygon) out << ' ' << id + base;
        out << '\n';
      }
      for (Index h = 0; h < facet.holes.rows(); ++h) {
        out << h + base;
        writeRowValues(out, facet.holes, h);
        out << '\n';
      }
    }
    out << "# part 3: holes\n" << file.holes.rows() << '\n';
    for (Index h = 0; h < file.holes.rows(); ++h) {
      out << h + base;
      writeRowValues(out, file.holes, h);
      out << '\n';
    }
    out << "# part 4: regions\n" << file.regions.size() << '\n';
    for (std::size_t r = 0; r < file.regions.size(); ++r) {
      const PolyRegion& region = file.regions[r];
      out << r + static_cast<std::size_t>(base);
      for (int k = 0; k < 3; ++k) {
        out << ' ';
        detail::writeDouble(out, region.point[k]);
      }
      out << ' ';
      detail::writeDouble(out, region.attribute);
      if (region.maxVolume > 0) {
        out << ' ';
        detail::writeDouble(out, region.maxVolume);
      }
      out << '\n';
    }
  });
}

TetMesh readTetMesh(const std::filesystem::path& nodePath, const std::filesystem::path& elePath,
                    int* eleFirstIndex) {
  TetMesh mesh;
  const NodeFile nodes = readNode(nodePath);
  const EleFile ele = readEle(elePath);
  if (eleFirstIndex) *eleFirstIndex = ele.firstIndex;
  mesh.nodes = nodes.points;
  // The .node file's numbering base is authoritative for the node references.
  mesh.elements = ele.corners().array() + (ele.firstIndex - nodes.firstIndex);
  validateTetMesh(mesh, elePath.string(), /*requirePositiveVolume=*/false);
  return mesh;
}

}  // namespace tetskin
