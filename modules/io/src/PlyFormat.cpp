// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/PlyFormat.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "PolygonTriangulation.h"
#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> typeNamed(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, Type>, 16> names{
      {{"char", Type::Int8},
       {"int8", Type::Int8},
       {"uchar", Type::UInt8},
       {"uint8", Type::UInt8},
       {"short", Type::Int16},
       {"int16", Type::Int16},
       {"ushort", Type::UInt16},
       {"uint16", Type::UInt16},
       {"int", Type::Int32},
       {"int32", Type::Int32},
       {"uint", Type::UInt32},
       {"uint32", Type::UInt32},
       {"float", Type::Float32},
       {"float32", Type::Float32},
       {"double", Type::Float64},
       {"float64", Type::Float64}}};
  for (const auto& [n, t] : names)
    if (n == name) return t;
  return std::nullopt;
}

std::size_t sizeOf(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
  }
  return 8;
}

bool isInteger(Type t) {
  return t != Type::Float32 && t != Type::Float64;
}

// What a vertex property is to TetSkin.
enum class Slot { None, X, Y, Z, NX, NY, NZ, U, V };

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool list = false;
  Type countType = Type::UInt8;
  Slot slot = Slot::None;
  bool faceIndices = false;  // the face element's vertex list
};

struct Element {
  std::string name;
  long long count = 0;
  long line = 0;
  std::vector<Property> properties;
};

enum class Format { Ascii, LittleEndian, BigEndian };

// The texture coordinate pairs PLY writers use, in order of preference.
constexpr std::array<std::pair<std::string_view, std::string_view>, 4> kTexturePairs{
    {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}};

// Values of the body, one at a time, from ascii tokens or binary bytes.
// Errors name the line (ascii) or the element and its number (binary).
class Values {
 public:
  // `lines` has just read the header's end_header line.
  Values(detail::TextLines& lines, std::string_view content, Format format)
      : lines_(lines), content_(content), format_(format) {
    if (format_ == Format::Ascii)
      token_ = lines_.size();  // the header line is used up
    else
      position_ = content_.size() - lines_.remainingBytes();
  }

  void enter(const Element& element, long long index) {
    element_ = &element;
    index_ = index;
  }

  // Ascii: FILE:LINE: message. Binary: FILE: vertex 12: message.
  [[noreturn]] void fail(const std::string& message) const {
    raise(format_ == Format::Ascii ? message : where() + ": " + message);
  }
  // FILE:LINE: vertex 12 message, or FILE: vertex 12 message.
  [[noreturn]] void failAbout(const std::string& message) const { raise(where() + " " + message); }

  // A value of type `t` as a double (integers up to 32 bits are exact).
  double read(Type t, const std::string& what) {
    if (format_ == Format::Ascii) {
      const std::string_view token = nextToken();
      if (isInteger(t)) return static_cast<double>(lines_.toInteger(token, what.c_str()));
      return lines_.toDouble(token, what.c_str());  // finite only
    }
    const std::size_t size = sizeOf(t);
    if (content_.size() - position_ < size) failEnd();
    unsigned char bytes[8];
    std::memcpy(bytes, content_.data() + position_, size);
    position_ += size;
    if ((format_ == Format::BigEndian) != (std::endian::native == std::endian::big))
      std::reverse(bytes, bytes + size);
    auto as = [&](auto value) {
      std::memcpy(&value, bytes, sizeof value);
      return static_cast<double>(value);
    };
    switch (t) {
      case Type::Int8:
        return as(std::int8_t{});
      case Type::UInt8:
        return as(std::uint8_t{});
      case Type::Int16:
        return as(std::int16_t{});
      case Type::UInt16:
        return as(std::uint16_t{});
      case Type::Int32:
        return as(std::int32_t{});
      case Type::UInt32:
        return as(std::uint32_t{});
      case Type::Float32:
        return as(float{});
      case Type::Float64:
        return as(double{});
    }
    return 0;
  }

  // At least how many bytes the rest of the body holds per value: a count
  // beyond what they can hold is corrupt and must not be allocated.
  std::size_t remainingBytes() const {
    return format_ == Format::Ascii ? lines_.remainingBytes() + lineRest()
                                    : content_.size() - position_;
  }
  std::size_t bytesPerValue(Type t) const {
    return format_ == Format::Ascii ? 2 : sizeOf(t);  // "0 " at the least
  }
  // ("0" ends an ascii file without a separator: one byte of slack.)
  bool canHold(long long values, std::size_t bytesEach) const {
    const std::size_t slack = format_ == Format::Ascii ? 1 : 0;
    return values >= 0 &&
           static_cast<unsigned long long>(values) <= (remainingBytes() + slack) / bytesEach;
  }

  // After the last element: nothing but white space may follow.
  void expectEnd() {
    if (format_ == Format::Ascii) {
      if (token_ < lines_.size() || lines_.next())
        lines_.fail("data after the last element (counts in the header too small?)");
      return;
    }
    const std::string_view rest = content_.substr(position_);
    if (rest.find_first_not_of(" \t\r\n") != std::string_view::npos)
      throw Error(lines_.sourceName(), 0,
                  std::to_string(rest.size()) +
                      " bytes after the last element (counts in the header too small?)");
  }

 private:
  std::string_view nextToken() {
    while (token_ >= lines_.size()) {
      if (!lines_.next()) failEnd();
      token_ = 0;
    }
    return lines_[token_++];
  }
  [[noreturn]] void failEnd() const {
    raise("the file ends inside " + where() + " (truncated file?)");
  }
  // The one way out: ascii errors name the current line, binary ones none.
  [[noreturn]] void raise(const std::string& message) const {
    if (format_ == Format::Ascii) lines_.fail(message);
    throw Error(lines_.sourceName(), 0, message);
  }
  std::string where() const {
    return element_ ? element_->name + " " + std::to_string(index_) : std::string("header");
  }
  std::size_t lineRest() const {
    std::size_t bytes = 0;
    for (std::size_t k = token_; k < lines_.size(); ++k) bytes += lines_[k].size() + 1;
    return bytes;
  }

  detail::TextLines& lines_;
  std::string_view content_;
  Format format_;
  std::size_t position_ = 0;  // binary
  std::size_t token_ = 0;     // ascii: the next token of the current line
  const Element* element_ = nullptr;
  long long index_ = 0;
};

class PlyParser {
 public:
  PlyParser(std::string_view content, const std::string& name)
      : content_(content), lines_(content, name, '\0') {}

  SurfaceMesh parse() {
    header();
    Values values(lines_, content_, format_);
    for (const Element& element : elements_) body(element, values);
    values.expectEnd();
    // (Polygons are triangulated once every vertex is read: a face element
    // may come before the vertex element.)
    for (std::size_t f = 0; f + 1 < faceStarts_.size(); ++f)
      detail::appendTriangles(
          std::vector<int>(faceCorners_.begin() + static_cast<std::ptrdiff_t>(faceStarts_[f]),
                           faceCorners_.begin() + static_cast<std::ptrdiff_t>(faceStarts_[f + 1])),
          [&](int v) { return Eigen::Vector3d(mesh_.positions.row(v).transpose()); }, triangles_);
    if (triangles_.empty()) throw Error(lines_.sourceName(), 0, "contains no triangles");
    mesh_.triangles.resize(static_cast<Index>(triangles_.size()), 3);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) mesh_.triangles(static_cast<Index>(t), k) = triangles_[t][k];
    return std::move(mesh_);
  }

 private:
  void header() {
    if (!lines_.next() || lines_[0] != "ply" || lines_.size() != 1)
      throw Error(lines_.sourceName(), 1, "not a PLY file (no 'ply' magic)");
    bool formatSeen = false;
    for (;;) {
      if (!lines_.next()) lines_.fail("the PLY header has no end_header");
      const std::string_view keyword = lines_[0];
      if (keyword == "end_header") break;
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "format") {
        lines_.expectTokens(3, 3, "format");
        if (lines_[1] == "ascii")
          format_ = Format::Ascii;
        else if (lines_[1] == "binary_little_endian")
          format_ = Format::LittleEndian;
        else if (lines_[1] == "binary_big_endian")
          format_ = Format::BigEndian;
        else
          lines_.fail("unknown PLY format '" + std::string(lines_[1]) + "'");
        formatSeen = true;
      } else if (keyword == "element") {
        lines_.expectTokens(3, 3, "element");
        Element e;
        e.name = lines_[1];
        e.count = lines_.toInteger(lines_[2], "element count");
        e.line = lines_.lineNumber();
        if (e.count < 0) lines_.fail("element count " + std::to_string(e.count) + " is negative");
        for (const Element& other : elements_)
          if (other.name == e.name) lines_.fail("a second '" + e.name + "' element");
        elements_.push_back(e);
      } else if (keyword == "property") {
        if (elements_.empty()) lines_.fail("a property before any element");
        elements_.back().properties.push_back(property());
      } else {
        lines_.fail("unknown PLY header line '" + std::string(keyword) + "'");
      }
    }
    if (!formatSeen) lines_.fail("the PLY header has no format line");
    assignSlots();
  }

  Property property() const {
    Property p;
    const auto type = [&](std::size_t k) {
      const std::optional<Type> t = typeNamed(lines_[k]);
      if (!t) lines_.fail("unknown PLY type '" + std::string(lines_[k]) + "'");
      return *t;
    };
    if (lines_.size() > 1 && lines_[1] == "list") {
      lines_.expectTokens(5, 5, "list property");
      p.list = true;
      p.countType = type(2);
      p.type = type(3);
      p.name = lines_[4];
      if (!isInteger(p.countType)) lines_.fail("a list's count type must be an integer type");
    } else {
      lines_.expectTokens(3, 3, "property");
      p.type = type(1);
      p.name = lines_[2];
    }
    return p;
  }

  // Finds the vertex and face elements and what their properties are.
  void assignSlots() {
    Element* vertex = nullptr;
    Element* face = nullptr;
    for (Element& e : elements_) {
      if (e.name == "vertex") vertex = &e;
      if (e.name == "face") face = &e;
    }
    const std::string& file = lines_.sourceName();
    if (!vertex) throw Error(file, 0, "the PLY file has no vertex element");
    auto find = [&](std::string_view name) -> Property* {
      for (Property& p : vertex->properties)
        if (p.name == name && !p.list) return &p;
      return nullptr;
    };
    const std::array<std::pair<std::string_view, Slot>, 6> axes{{{"x", Slot::X},
                                                                 {"y", Slot::Y},
                                                                 {"z", Slot::Z},
                                                                 {"nx", Slot::NX},
                                                                 {"ny", Slot::NY},
                                                                 {"nz", Slot::NZ}}};
    for (const auto& [name, slot] : axes)
      if (Property* p = find(name)) p->slot = slot;
    for (const char* axis : {"x", "y", "z"})
      if (!find(axis))
        throw Error(file, vertex->line, std::string("vertices have no '") + axis + "' property");
    hasNormals_ = find("nx") && find("ny") && find("nz");
    for (const auto& [u, v] : kTexturePairs)
      if (Property* pu = find(u), *pv = find(v); pu && pv) {
        pu->slot = Slot::U;
        pv->slot = Slot::V;
        hasTexcoords_ = true;
        break;
      }
    if (!hasNormals_)
      for (Property& p : vertex->properties)
        if (p.slot == Slot::NX || p.slot == Slot::NY || p.slot == Slot::NZ) p.slot = Slot::None;
    if (!face)
      throw Error(file, 0, "the PLY file has no face element (a point cloud, not a surface)");
    for (Property& p : face->properties)
      if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!isInteger(p.type))
          throw Error(file, face->line, "the face list '" + p.name + "' must hold integers");
        p.faceIndices = true;
        faceList_ = true;
        break;
      }
    if (!faceList_) throw Error(file, face->line, "faces have no vertex_indices list");
    vertexCount_ = vertex->count;
  }

  void body(const Element& element, Values& values) {
    if (element.properties.empty()) return;  // nothing to read, whatever the count
    std::size_t bytesEach = 0;
    for (const Property& p : element.properties)
      bytesEach += values.bytesPerValue(p.list ? p.countType : p.type);
    if (!values.canHold(element.count, bytesEach))
      throw Error(lines_.sourceName(), element.line,
                  "element '" + element.name + "' count " + std::to_string(element.count) +
                      " is more than the rest of the file can hold (truncated or corrupt file?)");
    const bool isVertex = element.name == "vertex";
    if (isVertex) {
      mesh_.positions.resize(element.count, 3);
      if (hasNormals_) mesh_.normals.resize(element.count, 3);
      if (hasTexcoords_) mesh_.texcoords.resize(element.count, 2);
    }
    if (element.name == "face") triangles_.reserve(static_cast<std::size_t>(element.count));
    // What ascii errors call each value ("vertex x 'abc' is not a number").
    std::vector<std::string> labels, countLabels;
    for (const Property& p : element.properties) {
      labels.push_back(element.name + " " + p.name);
      countLabels.push_back(labels.back() + " count");
    }
    std::vector<int> polygon;
    for (long long i = 0; i < element.count; ++i) {
      values.enter(element, i);
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& p = element.properties[k];
        if (!p.list) {
          const double value = values.read(p.type, labels[k]);
          if (isVertex && p.slot != Slot::None) store(values, i, p, value);
          continue;
        }
        const double count = values.read(p.countType, countLabels[k]);
        if (count < 0) values.fail("list '" + p.name + "' has a negative count");
        if (!values.canHold(static_cast<long long>(count), values.bytesPerValue(p.type)))
          values.fail(
              "list '" + p.name + "' of " + formatNumber(count) +
              " items is more than the rest of the file can hold (truncated or corrupt file?)");
        polygon.clear();
        for (long long item = 0; item < static_cast<long long>(count); ++item) {
          const double value = values.read(p.type, labels[k]);
          if (p.faceIndices) polygon.push_back(vertexIndex(values, value));
        }
        if (p.faceIndices) face(values, polygon);
      }
      // (x, y and z may come in any order: checked once the vertex is read.)
      if (isVertex)
        if (const std::string problem = coordinateProblem(mesh_.positions.row(i)); !problem.empty())
          values.failAbout(problem);
    }
  }

  void store(const Values& values, long long vertex, const Property& p, double value) {
    const auto v = static_cast<Index>(vertex);
    switch (p.slot) {
      case Slot::X:
      case Slot::Y:
      case Slot::Z:
        mesh_.positions(v, static_cast<int>(p.slot) - static_cast<int>(Slot::X)) = value;
        break;
      case Slot::NX:
      case Slot::NY:
      case Slot::NZ:
        if (!std::isfinite(value)) values.fail("normal component " + p.name + " is not finite");
        mesh_.normals(v, static_cast<int>(p.slot) - static_cast<int>(Slot::NX)) = value;
        break;
      case Slot::U:
      case Slot::V:
        if (!std::isfinite(value)) values.fail("texture coordinate " + p.name + " is not finite");
        mesh_.texcoords(v, static_cast<int>(p.slot) - static_cast<int>(Slot::U)) = value;
        break;
      case Slot::None:
        break;
    }
  }

  int vertexIndex(const Values& values, double item) const {
    if (item < 0 || item >= static_cast<double>(vertexCount_))
      values.fail("vertex index " + formatNumber(item) + " is out of range (" +
                  std::to_string(vertexCount_) + " vertices)");
    return static_cast<int>(item);
  }

  void face(const Values& values, const std::vector<int>& polygon) {
    if (polygon.size() < 3)
      values.fail("a face needs at least 3 vertices, found " + std::to_string(polygon.size()));
    faceCorners_.insert(faceCorners_.end(), polygon.begin(), polygon.end());
    faceStarts_.push_back(faceCorners_.size());
  }

  std::string_view content_;
  detail::TextLines lines_;
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  bool hasNormals_ = false, hasTexcoords_ = false, faceList_ = false;
  long long vertexCount_ = 0;
  SurfaceMesh mesh_;
  std::vector<int> faceCorners_;               // every face's corners in turn
  std::vector<std::size_t> faceStarts_ = {0};  // where each face starts in faceCorners_
  std::vector<std::array<int, 3>> triangles_;
};

}  // namespace

SurfaceMesh parsePly(std::string_view content, const std::string& sourceName) {
  return PlyParser(content, sourceName).parse();
}

SurfaceMesh readPly(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  return parsePly(content, path.string());
}

void writePly(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  validateSurface(mesh, path.string());
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment written by TetSkin\n"
        << "element vertex " << mesh.vertexCount() << "\n"
        << "property double x\nproperty double y\nproperty double z\n";
    if (mesh.hasNormals()) out << "property double nx\nproperty double ny\nproperty double nz\n";
    if (mesh.hasTexcoords()) out << "property double u\nproperty double v\n";
    out << "element face " << mesh.triangleCount() << "\n"
        << "property list uchar int vertex_indices\nend_header\n";
    auto put = [&](auto value) {
      unsigned char bytes[sizeof value];
      std::memcpy(bytes, &value, sizeof value);
      if constexpr (std::endian::native == std::endian::big)
        std::reverse(bytes, bytes + sizeof value);
      out.write(reinterpret_cast<const char*>(bytes), sizeof value);
    };
    for (Index v = 0; v < mesh.vertexCount(); ++v) {
      for (int k = 0; k < 3; ++k) put(mesh.positions(v, k));
      if (mesh.hasNormals())
        for (int k = 0; k < 3; ++k) put(mesh.normals(v, k));
      if (mesh.hasTexcoords())
        for (int k = 0; k < 2; ++k) put(mesh.texcoords(v, k));
    }
    for (Index t = 0; t < mesh.triangleCount(); ++t) {
      put(std::uint8_t{3});
      for (int k = 0; k < 3; ++k) put(std::int32_t{mesh.triangles(t, k)});
    }
  });
}

}  // namespace tetskin
