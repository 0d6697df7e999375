// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/GmshFormat.h"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "TextLines.h"
#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

using detail::TextLines;

// An element type's dimension and node count (Gmsh's numbering); the types
// Gmsh writes for linear and higher-order meshes.
struct ElementType {
  int dimension, nodes;
  const char* name;
};

const ElementType* elementType(long long type) {
  static const std::unordered_map<long long, ElementType> types = {
      {1, {1, 2, "line"}},          {2, {2, 3, "triangle"}},      {3, {2, 4, "quadrangle"}},
      {4, {3, 4, "tetrahedron"}},   {5, {3, 8, "hexahedron"}},    {6, {3, 6, "prism"}},
      {7, {3, 5, "pyramid"}},       {8, {1, 3, "line"}},          {9, {2, 6, "triangle"}},
      {10, {2, 9, "quadrangle"}},   {11, {3, 10, "tetrahedron"}}, {12, {3, 27, "hexahedron"}},
      {13, {3, 18, "prism"}},       {14, {3, 14, "pyramid"}},     {15, {0, 1, "point"}},
      {16, {2, 8, "quadrangle"}},   {17, {3, 20, "hexahedron"}},  {18, {3, 15, "prism"}},
      {19, {3, 13, "pyramid"}},     {20, {2, 9, "triangle"}},     {21, {2, 10, "triangle"}},
      {22, {2, 12, "triangle"}},    {23, {2, 15, "triangle"}},    {24, {2, 15, "triangle"}},
      {25, {2, 21, "triangle"}},    {26, {1, 4, "line"}},         {27, {1, 5, "line"}},
      {28, {1, 6, "line"}},         {29, {3, 20, "tetrahedron"}}, {30, {3, 35, "tetrahedron"}},
      {31, {3, 56, "tetrahedron"}}, {92, {3, 64, "hexahedron"}},  {93, {3, 125, "hexahedron"}}};
  const auto found = types.find(type);
  return found == types.end() ? nullptr : &found->second;
}

class Reader {
 public:
  Reader(std::string_view content, std::string sourceName)
      : lines_(content, std::move(sourceName), '\0') {}

  GmshTetrahedra read() {
    if (!lines_.next() || lines_[0] != "$MeshFormat")
      lines_.fail("is not a Gmsh mesh (.msh): it does not start with $MeshFormat");
    nextLine("the format line");
    lines_.expectTokens(3, 3, "format line (version, file type, data size)");
    const std::string version(lines_[0]);
    if (lines_.toInteger(lines_[1], "file type") != 0)
      lines_.fail(
          "is a binary .msh; save it as ASCII (gmsh -bin 0, or in Gmsh's window "
          "File > Export as .msh with Binary unchecked)");
    if (version == "4.1")
      version4_ = true;
    else if (version.rfind("2.", 0) != 0)
      lines_.fail("MSH format version " + version +
                  " is not read here; save as version 4.1 or 2.2 (gmsh -format msh41 or msh22)");
    endOf("MeshFormat");
    bool nodesRead = false, elementsRead = false;
    while (lines_.next()) {
      const std::string_view header = lines_[0];
      if (header == "$Nodes") {
        if (nodesRead) lines_.fail("a second $Nodes section");
        version4_ ? readNodes4() : readNodes2();
        nodesRead = true;
      } else if (header == "$Elements") {
        if (!nodesRead) lines_.fail("$Elements before $Nodes");
        if (elementsRead) lines_.fail("a second $Elements section");
        version4_ ? readElements4() : readElements2();
        elementsRead = true;
      } else if (header.size() > 1 && header[0] == '$') {
        skipSection(std::string(header.substr(1)));
      } else {
        lines_.fail("'" + std::string(header) + "' outside any section");
      }
    }
    if (!nodesRead || !elementsRead)
      lines_.fail(std::string("ends without a ") + (nodesRead ? "$Elements" : "$Nodes") +
                  " section");
    if (out_.elementTags.empty())
      lines_.fail("has no tetrahedra (a surface mesh? mesh the volume: gmsh -3)");
    out_.mesh.nodes = Points3(static_cast<Index>(points_.size()), 3);
    for (std::size_t i = 0; i < points_.size(); ++i)
      out_.mesh.nodes.row(static_cast<Index>(i)) << points_[i][0], points_[i][1], points_[i][2];
    out_.mesh.elements = Tetrahedra(static_cast<Index>(corners_.size()), 4);
    for (std::size_t e = 0; e < corners_.size(); ++e)
      for (int k = 0; k < 4; ++k) out_.mesh.elements(static_cast<Index>(e), k) = corners_[e][k];
    return std::move(out_);
  }

 private:
  TextLines lines_;
  bool version4_ = false;
  std::vector<std::array<double, 3>> points_;
  std::unordered_map<long long, int> nodeIndex_;  // tag -> index in points_
  std::vector<std::array<int, 4>> corners_;
  GmshTetrahedra out_;

  void nextLine(const char* what) {
    if (!lines_.next()) lines_.fail(std::string("ends before ") + what + " (truncated file?)");
  }
  // The next of `n` items of a section (item `i`, from 0), which must not
  // be the section's end or another section.
  void nextItem(long long i, long long n, const char* items) {
    nextLine(items);
    if (lines_[0].front() == '$')
      lines_.fail(std::string(lines_[0]) + " after " + std::to_string(i) + " of the " +
                  std::to_string(n) + " " + items + " announced (truncated section?)");
  }
  void endOf(const std::string& section) {
    nextLine(("$End" + section).c_str());
    if (lines_.size() != 1 || lines_[0] != "$End" + section)
      lines_.fail("expected $End" + section + ", found '" + std::string(lines_[0]) + "'");
  }
  void skipSection(const std::string& section) {
    const long start = lines_.lineNumber();
    while (lines_.next())
      if (lines_[0] == "$End" + section) return;
    throw Error(lines_.sourceName(), start, "$" + section + " has no $End" + section);
  }
  long long count(std::size_t token, const char* what, std::size_t minBytesPerItem) {
    const long long n = lines_.toInteger(lines_[token], what);
    lines_.checkCount(n, minBytesPerItem, what);
    return n;
  }
  void addNode(long long tag, const std::array<double, 3>& point) {
    if (!nodeIndex_.emplace(tag, static_cast<int>(points_.size())).second)
      lines_.fail("node tag " + std::to_string(tag) + " is listed twice");
    points_.push_back(point);
  }
  int nodeOf(std::string_view token, long long element) {
    const long long tag = lines_.toInteger(token, "node tag");
    const auto found = nodeIndex_.find(tag);
    if (found == nodeIndex_.end())
      lines_.fail("element " + std::to_string(element) + ": node tag " + std::to_string(tag) +
                  " is not in $Nodes");
    return found->second;
  }
  // The element on this line, of `type`, its nodes from token `first` on.
  void addElement(long long tag, long long typeNumber, std::size_t first) {
    const ElementType* type = elementType(typeNumber);
    if (!type)
      lines_.fail("element " + std::to_string(tag) + ": element type " +
                  std::to_string(typeNumber) + " is not one this reader knows");
    if (lines_.size() != first + static_cast<std::size_t>(type->nodes))
      lines_.fail("element " + std::to_string(tag) + ", a " + type->name + " of type " +
                  std::to_string(typeNumber) + ": expected " + std::to_string(type->nodes) +
                  " nodes, found " +
                  std::to_string(lines_.size() - std::min(first, lines_.size())));
    if (type->dimension < 3) {
      for (std::size_t k = first; k < lines_.size(); ++k) nodeOf(lines_[k], tag);
      ++out_.skippedElements;
      return;
    }
    if (std::string_view(type->name) != "tetrahedron")
      lines_.fail("element " + std::to_string(tag) + " is a " + type->name +
                  ": a dataset is made of tetrahedra (mesh with tetrahedra only)");
    std::array<int, 4> corners{};
    for (int k = 0; k < 4; ++k) corners[k] = nodeOf(lines_[first + k], tag);
    corners_.push_back(corners);
    out_.elementTags.push_back(tag);
  }

  void readNodes2() {
    nextLine("the node count");
    lines_.expectTokens(1, 1, "node count");
    const long long n = count(0, "node count", 8);  // "1 0 0 0\n"
    points_.reserve(static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i) {
      nextItem(i, n, "nodes");
      lines_.expectTokens(4, 4, "node (tag x y z)");
      addNode(lines_.toInteger(lines_[0], "node tag"), lines_.toPoint(1, "node"));
    }
    endOf("Nodes");
  }
  void readElements2() {
    nextLine("the element count");
    lines_.expectTokens(1, 1, "element count");
    const long long n = count(0, "element count", 8);  // "1 15 0 1\n"
    for (long long i = 0; i < n; ++i) {
      nextItem(i, n, "elements");
      lines_.expectTokens(3, 1000, "element (tag type tag-count tags... nodes...)");
      const long long tag = lines_.toInteger(lines_[0], "element tag");
      const long long tags = lines_.toInteger(lines_[2], "tag count");
      if (tags < 0 || static_cast<std::size_t>(tags) + 3 > lines_.size())
        lines_.fail("element " + std::to_string(tag) + ": tag count " + std::to_string(tags) +
                    " does not fit the line");
      addElement(tag, lines_.toInteger(lines_[1], "element type"),
                 3 + static_cast<std::size_t>(tags));
    }
    endOf("Elements");
  }
  void readNodes4() {
    nextLine("the node header");
    lines_.expectTokens(4, 4, "node header (blocks, nodes, smallest and largest tag)");
    const long long blocks = count(0, "node block count", 8);
    const long long total = count(1, "node count", 8);
    points_.reserve(static_cast<std::size_t>(total));
    for (long long b = 0; b < blocks; ++b) {
      nextItem(b, blocks, "node blocks");
      lines_.expectTokens(4, 4, "node block header (dimension, entity, parametric, nodes)");
      const long long parametric = lines_.toInteger(lines_[2], "parametric flag");
      const long long n = count(3, "block node count", 4);
      std::vector<long long> tags(static_cast<std::size_t>(n));
      for (long long& tag : tags) {
        nextItem(&tag - tags.data(), n, "node tags of the block");
        lines_.expectTokens(1, 1, "node tag");
        tag = lines_.toInteger(lines_[0], "node tag");
      }
      for (std::size_t i = 0; i < tags.size(); ++i) {
        const long long tag = tags[i];
        nextItem(static_cast<long long>(i), n, "node positions of the block");
        // (Parametric coordinates, if any, follow x y z: 1 to 3 of them.)
        lines_.expectTokens(3, parametric ? 6 : 3, "node coordinates");
        addNode(tag, lines_.toPoint(0, "node"));
      }
    }
    if (static_cast<long long>(points_.size()) != total)
      lines_.fail("the node header counts " + std::to_string(total) + " nodes, the blocks " +
                  std::to_string(points_.size()));
    endOf("Nodes");
  }
  void readElements4() {
    nextLine("the element header");
    lines_.expectTokens(4, 4, "element header (blocks, elements, smallest and largest tag)");
    const long long blocks = count(0, "element block count", 8);
    const long long total = count(1, "element count", 4);
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      nextItem(b, blocks, "element blocks");
      lines_.expectTokens(4, 4, "element block header (dimension, entity, type, elements)");
      const long long type = lines_.toInteger(lines_[2], "element type");
      const long long n = count(3, "block element count", 4);
      for (long long i = 0; i < n; ++i) {
        nextItem(i, n, "elements of the block");
        addElement(lines_.toInteger(lines_[0], "element tag"), type, 1);
      }
      seen += n;
    }
    if (seen != total)
      lines_.fail("the element header counts " + std::to_string(total) + " elements, the blocks " +
                  std::to_string(seen));
    endOf("Elements");
  }
};

}  // namespace

GmshTetrahedra parseGmshTetrahedra(std::string_view content, const std::string& sourceName) {
  return Reader(content, sourceName).read();
}

GmshTetrahedra readGmshTetrahedra(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  return parseGmshTetrahedra(content, path.string());
}

}  // namespace tetskin
