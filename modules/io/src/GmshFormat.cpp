// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/GmshFormat.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

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

// What both encodings read into: the nodes by tag, the tetrahedra's
// corners, the elements left out. `fail` raises the encoding's error (with
// its line, or its byte offset).
class Collector {
 public:
  using Fail = std::function<void(const std::string&)>;
  explicit Collector(Fail fail) : fail_(std::move(fail)) {}

  void reserveNodes(long long n) { points_.reserve(static_cast<std::size_t>(n)); }
  std::size_t nodeCount() const { return points_.size(); }

  void addNode(long long tag, const std::array<double, 3>& point) {
    if (!nodeIndex_.emplace(tag, static_cast<int>(points_.size())).second)
      fail("node tag " + std::to_string(tag) + " is listed twice");
    points_.push_back(point);
  }
  // An element of Gmsh type `typeNumber` with node tags `nodes` (checked
  // to be as many as its type has).
  void addElement(long long tag, long long typeNumber, const std::vector<long long>& nodes) {
    const ElementType* type = elementTypeOf(tag, typeNumber);
    if (nodes.size() != static_cast<std::size_t>(type->nodes))
      fail("element " + std::to_string(tag) + ", a " + type->name + " of type " +
           std::to_string(typeNumber) + ": expected " + std::to_string(type->nodes) +
           " nodes, found " + std::to_string(nodes.size()));
    if (type->dimension < 3) {
      for (long long node : nodes) nodeOf(node, tag);
      ++out_.skippedElements;
      return;
    }
    if (std::string_view(type->name) != "tetrahedron")
      fail("element " + std::to_string(tag) + " is a " + type->name +
           ": a dataset is made of tetrahedra (mesh with tetrahedra only)");
    std::array<int, 4> corners{};
    for (int k = 0; k < 4; ++k) corners[k] = nodeOf(nodes[static_cast<std::size_t>(k)], tag);
    corners_.push_back(corners);
    out_.elementTags.push_back(tag);
  }
  // The element type's node count; fails for a type this reader does not know.
  int nodesOfType(long long tag, long long typeNumber) const {
    return elementTypeOf(tag, typeNumber)->nodes;
  }

  GmshTetrahedra finish() {
    if (out_.elementTags.empty())
      fail("has no tetrahedra (a surface mesh? mesh the volume: gmsh -3)");
    out_.mesh.nodes = Points3(static_cast<Index>(points_.size()), 3);
    for (std::size_t i = 0; i < points_.size(); ++i)
      out_.mesh.nodes.row(static_cast<Index>(i)) << points_[i][0], points_[i][1], points_[i][2];
    out_.mesh.elements = Tetrahedra(static_cast<Index>(corners_.size()), 4);
    for (std::size_t e = 0; e < corners_.size(); ++e)
      for (int k = 0; k < 4; ++k) out_.mesh.elements(static_cast<Index>(e), k) = corners_[e][k];
    return std::move(out_);
  }

  [[noreturn]] void fail(const std::string& what) const {
    fail_(what);
    throw Error(what);  // (fail_ throws; this keeps the compiler sure of it)
  }

 private:
  Fail fail_;
  std::vector<std::array<double, 3>> points_;
  std::unordered_map<long long, int> nodeIndex_;  // tag -> index in points_
  std::vector<std::array<int, 4>> corners_;
  GmshTetrahedra out_;

  const ElementType* elementTypeOf(long long tag, long long typeNumber) const {
    const ElementType* type = elementType(typeNumber);
    if (!type)
      fail("element " + std::to_string(tag) + ": element type " + std::to_string(typeNumber) +
           " is not one this reader knows");
    return type;
  }
  int nodeOf(long long tag, long long element) const {
    const auto found = nodeIndex_.find(tag);
    if (found == nodeIndex_.end())
      fail("element " + std::to_string(element) + ": node tag " + std::to_string(tag) +
           " is not in $Nodes");
    return found->second;
  }
};

// The binary encoding (file type 1): section headers as text lines, the
// records as the writer's machine stored them (Gmsh writes the integer 1
// after the format line, so the byte order shows). Errors name the byte
// offset, as the file has no lines to name.
class BinaryReader {
 public:
  BinaryReader(std::string_view content, std::string sourceName, std::size_t position,
               bool version4, int dataSize)
      : content_(content),
        name_(std::move(sourceName)),
        at_(position),
        version4_(version4),
        dataSize_(dataSize),
        collect_([this](const std::string& what) { fail(what); }) {}

  GmshTetrahedra read() {
    const std::size_t oneAt = at_;
    const std::uint32_t one = raw<std::uint32_t>("the byte order check (the integer 1)");
    if (one == 1) {
      swap_ = false;
    } else if (byteSwapped(one) == 1) {
      swap_ = true;
    } else {
      at_ = oneAt;
      fail(
          "the byte order check after the format line is not the integer 1 in either byte "
          "order (not a binary .msh, or a damaged one)");
    }
    endOf("MeshFormat");
    bool nodesRead = false, elementsRead = false;
    while (true) {
      skipLineEnds();
      if (at_ >= content_.size()) break;
      const std::string header = line("a section header");
      if (header == "$Nodes") {
        if (nodesRead) fail("a second $Nodes section");
        version4_ ? readNodes4() : readNodes2();
        nodesRead = true;
      } else if (header == "$Elements") {
        if (!nodesRead) fail("$Elements before $Nodes");
        if (elementsRead) fail("a second $Elements section");
        version4_ ? readElements4() : readElements2();
        elementsRead = true;
      } else if (header.size() > 1 && header[0] == '$') {
        skipSection(header.substr(1));
      } else {
        fail("'" + header.substr(0, 40) + "' outside any section");
      }
    }
    if (!nodesRead || !elementsRead)
      fail(std::string("ends without a ") + (nodesRead ? "$Elements" : "$Nodes") + " section");
    return collect_.finish();
  }

 private:
  std::string_view content_;
  std::string name_;
  std::size_t at_;
  bool version4_;
  int dataSize_;  // bytes of a size_t in 4.1
  bool swap_ = false;
  Collector collect_;

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_, 0, "byte " + std::to_string(at_) + ": " + what);
  }
  static std::uint32_t byteSwapped(std::uint32_t v) {
    return ((v & 0xffu) << 24) | ((v & 0xff00u) << 8) | ((v >> 8) & 0xff00u) | (v >> 24);
  }
  template <typename T>
  T raw(const char* what) {
    if (content_.size() - at_ < sizeof(T))
      fail(std::string("the file ends inside ") + what + " (truncated file?)");
    T value;
    std::memcpy(&value, content_.data() + at_, sizeof(T));
    if (swap_) {
      char* bytes = reinterpret_cast<char*>(&value);
      std::reverse(bytes, bytes + sizeof(T));
    }
    at_ += sizeof(T);
    return value;
  }
  long long integer(const char* what) { return raw<std::int32_t>(what); }
  long long size(const char* what) {
    const std::uint64_t v =
        dataSize_ == 8 ? raw<std::uint64_t>(what) : std::uint64_t{raw<std::uint32_t>(what)};
    if (v > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
      fail(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<long long>(v);
  }
  // Fails when `count` items of `bytesPerItem` bytes cannot fit in the rest
  // of the file, so a corrupt count never allocates absurdly.
  void checkCount(long long count, std::size_t bytesPerItem, const char* what) const {
    if (count < 0 || (bytesPerItem > 0 && static_cast<unsigned long long>(count) >
                                              (content_.size() - at_) / bytesPerItem))
      fail(std::string(what) + " " + std::to_string(count) +
           " is more than the rest of the file can hold (truncated file?)");
  }
  // Node `tag`'s coordinates.
  std::array<double, 3> point(long long tag) {
    std::array<double, 3> p{};
    for (double& x : p) x = raw<double>("a node's coordinates");
    if (const std::string problem = coordinateProblem(Eigen::RowVector3d(p[0], p[1], p[2]));
        !problem.empty())
      fail("node " + std::to_string(tag) + " " + problem);
    return p;
  }
  void skipLineEnds() {
    while (at_ < content_.size() && (content_[at_] == '\n' || content_[at_] == '\r')) ++at_;
  }
  // The text line from here (without its line end).
  std::string line(const char* what) {
    skipLineEnds();
    if (at_ >= content_.size()) fail(std::string("the file ends before ") + what);
    const std::size_t end = content_.find('\n', at_);
    std::string text(
        content_.substr(at_, end == std::string_view::npos ? std::string_view::npos : end - at_));
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
    at_ = end == std::string_view::npos ? content_.size() : end + 1;
    return text;
  }
  void endOf(const std::string& section) {
    const std::string text = line(("$End" + section).c_str());
    if (text != "$End" + section)
      fail("expected $End" + section + ", found '" + text.substr(0, 40) + "'");
  }
  void skipSection(const std::string& section) {
    const std::string end = "\n$End" + section;
    const std::size_t found = content_.find(end, at_ == 0 ? 0 : at_ - 1);
    if (found == std::string_view::npos) fail("$" + section + " has no $End" + section);
    at_ = found + end.size();
  }
  // A count on a text line of its own (2.2's sections start so).
  long long textCount(const char* what) {
    const std::string text = line(what);
    long long n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error != std::errc() || end != text.data() + text.size() || n < 0)
      fail(std::string(what) + " '" + text.substr(0, 40) + "' is not a whole number");
    return n;
  }

  void readNodes2() {
    const long long n = textCount("the node count");
    checkCount(n, 4 + 3 * 8, "node count");
    collect_.reserveNodes(n);
    for (long long i = 0; i < n; ++i) {
      const long long tag = integer("a node's tag");
      collect_.addNode(tag, point(tag));
    }
    endOf("Nodes");
  }
  void readElements2() {
    const long long n = textCount("the element count");
    checkCount(n, 4 * 4, "element count");
    long long seen = 0;
    std::vector<long long> nodes;
    while (seen < n) {
      const long long type = integer("an element block's type");
      const long long follow = integer("an element block's count");
      const long long tags = integer("an element block's tag count");
      if (follow < 1 || follow > n - seen)
        fail("an element block of " + std::to_string(follow) + " elements, where " +
             std::to_string(n - seen) + " of the " + std::to_string(n) + " announced remain");
      if (tags < 0 || tags > 1000) fail("an element block's tag count " + std::to_string(tags));
      const int perElement = collect_.nodesOfType(-1, type);
      checkCount(follow, 4 * static_cast<std::size_t>(1 + tags + perElement), "element count");
      for (long long i = 0; i < follow; ++i) {
        const long long tag = integer("an element's number");
        for (long long t = 0; t < tags; ++t) integer("an element's tag");
        nodes.resize(static_cast<std::size_t>(perElement));
        for (long long& node : nodes) node = integer("an element's node");
        collect_.addElement(tag, type, nodes);
      }
      seen += follow;
    }
    endOf("Elements");
  }
  void readNodes4() {
    const long long blocks = size("the node block count");
    const long long total = size("the node count");
    size("the smallest node tag");
    size("the largest node tag");
    checkCount(total, static_cast<std::size_t>(dataSize_) + 3 * 8, "node count");
    checkCount(blocks, 3 * 4 + static_cast<std::size_t>(dataSize_), "node block count");
    collect_.reserveNodes(total);
    for (long long b = 0; b < blocks; ++b) {
      const long long dimension = integer("a node block's dimension");
      integer("a node block's entity");
      const long long parametric = integer("a node block's parametric flag");
      const long long n = size("a node block's node count");
      if (dimension < 0 || dimension > 3)
        fail("node block " + std::to_string(b) + ": dimension " + std::to_string(dimension));
      const long long extra = parametric ? dimension : 0;  // u, v, w after x, y, z
      checkCount(n, static_cast<std::size_t>(dataSize_) + static_cast<std::size_t>(3 + extra) * 8,
                 "node block's node count");
      std::vector<long long> tags(static_cast<std::size_t>(n));
      for (long long& tag : tags) tag = size("a node's tag");
      for (long long tag : tags) {
        collect_.addNode(tag, point(tag));
        for (long long k = 0; k < extra; ++k) raw<double>("a node's parametric coordinate");
      }
    }
    if (static_cast<long long>(collect_.nodeCount()) != total)
      fail("the node header counts " + std::to_string(total) + " nodes, the blocks " +
           std::to_string(collect_.nodeCount()));
    endOf("Nodes");
  }
  void readElements4() {
    const long long blocks = size("the element block count");
    const long long total = size("the element count");
    size("the smallest element tag");
    size("the largest element tag");
    checkCount(total, 2 * static_cast<std::size_t>(dataSize_), "element count");
    checkCount(blocks, 3 * 4 + static_cast<std::size_t>(dataSize_), "element block count");
    long long seen = 0;
    std::vector<long long> nodes;
    for (long long b = 0; b < blocks; ++b) {
      integer("an element block's dimension");
      integer("an element block's entity");
      const long long type = integer("an element block's type");
      const long long n = size("an element block's element count");
      const int perElement = collect_.nodesOfType(-1, type);
      checkCount(n, static_cast<std::size_t>(dataSize_) * static_cast<std::size_t>(1 + perElement),
                 "element block's element count");
      for (long long i = 0; i < n; ++i) {
        const long long tag = size("an element's tag");
        nodes.resize(static_cast<std::size_t>(perElement));
        for (long long& node : nodes) node = size("an element's node");
        collect_.addElement(tag, type, nodes);
      }
      seen += n;
    }
    if (seen != total)
      fail("the element header counts " + std::to_string(total) + " elements, the blocks " +
           std::to_string(seen));
    endOf("Elements");
  }
};

class Reader {
 public:
  Reader(std::string_view content, std::string sourceName)
      : content_(content),
        lines_(content, std::move(sourceName), '\0'),
        collect_([this](const std::string& what) { lines_.fail(what); }) {}

  GmshTetrahedra read() {
    if (!lines_.next() || lines_[0] != "$MeshFormat")
      lines_.fail("is not a Gmsh mesh (.msh): it does not start with $MeshFormat");
    nextLine("the format line");
    lines_.expectTokens(3, 3, "format line (version, file type, data size)");
    const std::string version(lines_[0]);
    const long long fileType = lines_.toInteger(lines_[1], "file type");
    if (fileType != 0 && fileType != 1)
      lines_.fail("file type " + std::to_string(fileType) + " is neither 0 (ASCII) nor 1 (binary)");
    if (version == "4.1")
      version4_ = true;
    else if (version.rfind("2.", 0) != 0)
      lines_.fail("MSH format version " + version +
                  " is not read here; save as version 4.1 or 2.2 (gmsh -format msh41 or msh22)");
    if (fileType == 1) {
      const long long dataSize = lines_.toInteger(lines_[2], "data size");
      if (dataSize != 4 && dataSize != 8)
        lines_.fail("data size " + std::to_string(dataSize) + " is neither 4 nor 8 bytes");
      // The binary part starts right after the format line's line end.
      const std::size_t position = content_.size() - lines_.remainingBytes();
      return BinaryReader(content_, lines_.sourceName(), position, version4_,
                          static_cast<int>(dataSize))
          .read();
    }
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
    return collect_.finish();
  }

 private:
  std::string_view content_;
  TextLines lines_;
  bool version4_ = false;
  Collector collect_;

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
  // The element on this line, of `type`, its nodes from token `first` on.
  void addElement(long long tag, long long typeNumber, std::size_t first) {
    std::vector<long long> nodes;
    for (std::size_t k = first; k < lines_.size(); ++k)
      nodes.push_back(lines_.toInteger(lines_[k], "node tag"));
    collect_.addElement(tag, typeNumber, nodes);
  }

  void readNodes2() {
    nextLine("the node count");
    lines_.expectTokens(1, 1, "node count");
    const long long n = count(0, "node count", 8);  // "1 0 0 0\n"
    collect_.reserveNodes(n);
    for (long long i = 0; i < n; ++i) {
      nextItem(i, n, "nodes");
      lines_.expectTokens(4, 4, "node (tag x y z)");
      collect_.addNode(lines_.toInteger(lines_[0], "node tag"), lines_.toPoint(1, "node"));
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
    collect_.reserveNodes(total);
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
        collect_.addNode(tag, lines_.toPoint(0, "node"));
      }
    }
    if (static_cast<long long>(collect_.nodeCount()) != total)
      lines_.fail("the node header counts " + std::to_string(total) + " nodes, the blocks " +
                  std::to_string(collect_.nodeCount()));
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
