// SPDX-License-Identifier: AGPL-3.0-or-later
#include "VtkXmlHeader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <fstream>
#include <istream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "tetskin/core/Error.h"

namespace tetskin::detail {
namespace {

// The array types of VTK's XML formats that its 9.1 reader handles.
constexpr std::array<std::string_view, 12> kArrayTypes{"Int8",    "UInt8",   "Int16",  "UInt16",
                                                       "Int32",   "UInt32",  "Int64",  "UInt64",
                                                       "Float32", "Float64", "String", "Bit"};

constexpr std::array<std::string_view, 8> kIntegerTypes{"Int8",  "UInt8",  "Int16", "UInt16",
                                                        "Int32", "UInt32", "Int64", "UInt64"};
constexpr std::array<std::string_view, 5> kCellSections{"Cells", "Verts", "Lines", "Strips",
                                                        "Polys"};

// The value of attribute `name` in a tag's text, or nullopt.
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    // A whole attribute name: preceded by white space, followed by ="
    const bool starts =
        at > 0 && std::string_view(" \t\r\n").find(tag[at - 1]) != std::string_view::npos;
    const std::size_t quote = at + name.size() + 1;
    if (!starts || quote >= tag.size() || tag[at + name.size()] != '=' || tag[quote] != '"')
      continue;
    const std::size_t end = tag.find('"', quote + 1);
    if (end == std::string_view::npos) return std::nullopt;
    return tag.substr(quote + 1, end - quote - 1);
  }
  return std::nullopt;
}

bool isWholeNumber(std::string_view text, long long minimum,
                   long long maximum = std::numeric_limits<long long>::max()) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value >= minimum &&
         value <= maximum;
}

// The tags of a VTK XML file's XML part, one at a time, with the line each
// starts on and where in the file (bytes) it starts and ends. The text
// between tags (inline data, possibly most of the file) is read past in
// chunks and not kept; the XML part ends at the end of the file, at an
// unclosed tag (VTK's parser reports it) or at <AppendedData (the raw bytes
// after it are not XML).
class XmlTags {
 public:
  explicit XmlTags(std::istream& in) : in_(in) {}

  // The next tag's text from '<' up to its '>' (excluded), and the offset of
  // its '<'; false at the end, and at <AppendedData ...> (then appended()).
  bool next(std::string& tag, long& line, std::uint64_t& start) {
    if (!readUntil('<', nullptr)) return false;
    line = line_;
    start = position();
    tag.clear();
    if (!readUntil('>', &tag)) return false;
    ++at_;  // past '>'
    appended_ = tag.rfind("<AppendedData", 0) == 0;
    return !appended_;
  }
  // Whether next() stopped at <AppendedData ...> (its tag read, `position()`
  // just past it).
  bool appended() const { return appended_; }
  // The offset of the next byte not yet read past.
  std::uint64_t position() const { return chunkBegin_ + at_; }
  // Reads past white space: the next other byte (left unread), nullopt at
  // the end of the file.
  std::optional<char> skipSpace() {
    for (;; ++at_) {
      if (at_ == chunk_.size() && !refill()) return std::nullopt;
      if (!std::isspace(static_cast<unsigned char>(chunk_[at_]))) return chunk_[at_];
    }
  }

 private:
  bool refill() {
    chunkBegin_ += chunk_.size();
    chunk_.resize(1 << 20);
    in_.read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
    chunk_.resize(static_cast<std::size_t>(in_.gcount()));
    at_ = 0;
    return !chunk_.empty();
  }
  // Reads up to the next `c` (left unread), counting lines and appending
  // the text to `kept` if given; false at the end of the file.
  bool readUntil(char c, std::string* kept) {
    for (;;) {
      if (at_ == chunk_.size() && !refill()) return false;
      const std::string_view rest(chunk_.data() + at_, chunk_.size() - at_);
      const std::size_t found = rest.find(c);
      const std::string_view part = rest.substr(0, found);
      line_ += static_cast<long>(std::count(part.begin(), part.end(), '\n'));
      if (kept) *kept += part;
      at_ += part.size();
      if (found != std::string_view::npos) return true;
    }
  }

  std::istream& in_;
  std::string chunk_;
  std::uint64_t chunkBegin_ = 0;  // the file offset of chunk_[0]
  std::size_t at_ = 0;
  long line_ = 1;
  bool appended_ = false;
};

// A VTKFile type as a reader knows it: "PolyData (.vtp)".
std::string describeType(std::string_view type) {
  constexpr std::array<std::array<std::string_view, 2>, 3> kExtensions{
      {{"PolyData", ".vtp"}, {"UnstructuredGrid", ".vtu"}, {"Collection", ".pvd"}}};
  for (const auto& [name, extension] : kExtensions)
    if (type == name) return std::string(name) + " (" + std::string(extension) + ")";
  return "'" + std::string(type) + "'";
}

// More components than any array TetSkin or ParaView users write (VTK hung
// on 99999999999).
constexpr long long kMaxComponents = 4096;

// A Piece's size attribute as a count (0 when absent; checked before).
long long pieceCount(std::string_view tag, const std::string& name) {
  long long value = 0;
  if (const auto text = attribute(tag, name))
    std::from_chars(text->data(), text->data() + text->size(), value);
  return value;
}

}  // namespace

VtkXmlLayout checkVtkXmlHeader(const std::filesystem::path& path, std::string_view expectedType) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open for reading");
  const std::string file = path.string();
  VtkXmlLayout layout;
  // Inside a cell section (Cells of a .vtu; Verts, Lines, Strips, Polys of
  // a .vtp), whose offsets and connectivity must be integers: VTK crashed
  // on float offsets in a .vtu.
  std::string cellSection;
  int cellSections = 0;
  long long cellSectionCells = 0;
  // Inside Points, PointData, CellData or FieldData: what an array's tuple
  // count is.
  std::string dataSection;
  long long points = 0, cells = 0;  // the current Piece's
  std::string pieceTag;
  XmlTags tags(in);
  std::string tagText;
  long line = 0;
  std::uint64_t tagStart = 0;
  bool rootSeen = false;
  // The array whose inline text runs up to the next tag.
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::size_t open = kNone;
  while (tags.next(tagText, line, tagStart)) {
    if (open != kNone) layout.arrays[open].textEnd = tagStart;
    open = kNone;
    const std::string_view tag(tagText);
    if (tag.substr(0, 2) == "<?" || tag.substr(0, 2) == "<!") continue;  // declaration, comment
    const std::string_view name = tag.substr(1, tag.find_first_of(" \t\r\n/") - 1);
    if (!rootSeen) {
      // Checked first: any other file (an OBJ, a .pvd, a .vtu where a .vtp
      // belongs) would otherwise get VTK's parser messages.
      if (name != "VTKFile") break;
      rootSeen = true;
      const std::string_view type = attribute(tag, "type").value_or("");
      if (type != expectedType)
        throw Error(file, line,
                    "is a VTK " + describeType(type) + " file, not " + describeType(expectedType) +
                        (type == "Collection" ? " (a series: give one of its files)" : ""));
      layout.rootLine = line;
      layout.headerBytes = attribute(tag, "header_type") == "UInt64" ? 8 : 4;
      layout.bigEndian = attribute(tag, "byte_order") == "BigEndian";
      layout.compressor = attribute(tag, "compressor").value_or("");
      continue;
    }
    if (tag.substr(0, 2) == "</") {  // a closing tag
      const std::string_view closed = tag.substr(2);
      if (std::find(kCellSections.begin(), kCellSections.end(), closed) != kCellSections.end())
        cellSection.clear();
      if (closed == dataSection) dataSection.clear();
      continue;
    }
    if (std::find(kCellSections.begin(), kCellSections.end(), name) != kCellSections.end()) {
      cellSection = name;
      ++cellSections;
      // (Its offsets: a value per cell of its kind.)
      cellSectionCells = pieceCount(pieceTag, "NumberOf" + std::string(name));
    }
    if (name == "Points" || name == "PointData" || name == "CellData" || name == "FieldData")
      dataSection = name;
    const std::string arrayName(attribute(tag, "Name").value_or("?"));
    if (name == "Array" || name == "DataArray") {
      const auto type = attribute(tag, "type");
      if (!type || std::find(kArrayTypes.begin(), kArrayTypes.end(), *type) == kArrayTypes.end())
        throw Error(file, line,
                    std::string(name) + " '" + arrayName + "': unknown type '" +
                        std::string(type.value_or("")) + "'");
      // VTK writes string arrays as Array elements, numbers as DataArray;
      // it crashed on a DataArray declared String (point or field data).
      if (*type == "String" && name == "DataArray")
        throw Error(file, line,
                    "DataArray '" + arrayName + "': type String (strings are Array elements)");
      if (!cellSection.empty() && (arrayName == "offsets" || arrayName == "connectivity") &&
          std::find(kIntegerTypes.begin(), kIntegerTypes.end(), *type) == kIntegerTypes.end())
        throw Error(file, line,
                    std::string(cellSection) + " " + arrayName + ": type '" + std::string(*type) +
                        "' is not an integer type");
      const auto components = attribute(tag, "NumberOfComponents");
      if (components && !isWholeNumber(*components, 1, kMaxComponents))
        throw Error(file, line,
                    std::string(name) + " '" + arrayName + "': NumberOfComponents '" +
                        std::string(*components) + "' is not a whole number in [1, " +
                        std::to_string(kMaxComponents) + "]");
      // VTK leaked the points it had allocated where they were not 3-vectors.
      if (dataSection == "Points" && (!components || pieceCount(tag, "NumberOfComponents") != 3))
        throw Error(file, line,
                    "Points '" + arrayName + "': " +
                        (components ? "NumberOfComponents '" + std::string(*components) + "'"
                                    : std::string("no NumberOfComponents")) +
                        " (points have 3)");
      const auto tuples = attribute(tag, "NumberOfTuples");
      if (tuples && !isWholeNumber(*tuples, 0))
        throw Error(file, line,
                    std::string(name) + " '" + arrayName + "': NumberOfTuples '" +
                        std::string(*tuples) + "' is not a whole number >= 0");
      VtkXmlArray array;
      array.name = arrayName;
      array.type = *type;
      array.components = components ? pieceCount(tag, "NumberOfComponents") : 1;
      array.format = attribute(tag, "format").value_or("ascii");
      if (const auto offset = attribute(tag, "offset"))
        std::from_chars(offset->data(), offset->data() + offset->size(), array.offset);
      array.line = line;
      array.textBegin = array.textEnd = tags.position();
      if (!cellSection.empty()) {
        array.cellSection = cellSections - 1;
        if (arrayName == "offsets" || arrayName == "types") {
          array.role = VtkXmlArray::Role::Sized;
          array.tuples = arrayName == "types" ? cells : cellSectionCells;
        } else if (arrayName == "connectivity") {
          array.role = VtkXmlArray::Role::Connectivity;
        }
      } else if (dataSection == "FieldData") {
        if (tuples) {
          array.role = VtkXmlArray::Role::Field;
          array.tuples = pieceCount(tag, "NumberOfTuples");
        }
      } else if (dataSection == "Points" || dataSection == "PointData") {
        array.role = VtkXmlArray::Role::Sized;
        array.tuples = points;
      } else if (dataSection == "CellData") {
        array.role = VtkXmlArray::Role::Sized;
        array.tuples = cells;
      }
      if (tag.back() != '/') open = layout.arrays.size();  // inline text follows
      layout.arrays.push_back(std::move(array));
    } else if (name == "Piece") {
      for (std::string_view size : {"NumberOfPoints", "NumberOfCells", "NumberOfVerts",
                                    "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        if (const auto n = attribute(tag, size); n && !isWholeNumber(*n, 0))
          throw Error(file, line,
                      "Piece: " + std::string(size) + " '" + std::string(*n) +
                          "' is not a whole number >= 0");
      points = pieceCount(tag, "NumberOfPoints");
      pieceTag = tagText;
      // (A .vtu's cells, or a .vtp's four kinds together: what its CellData
      // holds a tuple for.)
      cells = pieceCount(tag, "NumberOfCells");
      for (const char* kind : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        cells += pieceCount(tag, kind);
    }
  }
  if (!rootSeen) throw Error(file, 0, "is not a VTK XML file (no <VTKFile> root element)");
  if (tags.appended()) {
    // The data start after the '_' that VTK writes after white space; as
    // VTK's reader has it, where another byte stands there the data start
    // with it (the tag's attributes are in tagText).
    layout.appendedBase64 = attribute(tagText, "encoding") == "base64";
    if (const std::optional<char> first = tags.skipSpace())
      layout.appendedBegin = tags.position() + (*first == '_' ? 1 : 0);
  }
  return layout;
}

}  // namespace tetskin::detail
