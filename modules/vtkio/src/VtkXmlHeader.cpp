// SPDX-License-Identifier: AGPL-3.0-or-later
#include "VtkXmlHeader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
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

// More components than any array TetSkin or ParaView users write (VTK hung
// on 99999999999).
constexpr long long kMaxComponents = 4096;

}  // namespace

void checkVtkXmlHeader(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open for reading");
  // The XML before the appended (binary) data; all of it when there is none.
  std::string xml;
  for (std::string line; std::getline(in, line);) {
    if (line.find("<AppendedData") != std::string::npos) break;
    xml += line;
    xml += '\n';
  }
  const std::string file = path.string();
  // Inside a cell section (Cells of a .vtu; Verts, Lines, Strips, Polys of
  // a .vtp), whose offsets and connectivity must be integers: VTK crashed
  // on float offsets in a .vtu.
  std::string_view cellSection;
  long line = 1;
  std::size_t counted = 0;  // newlines counted up to here
  std::size_t at = 0;
  while ((at = xml.find('<', at)) != std::string::npos) {
    const std::size_t end = xml.find('>', at);
    if (end == std::string::npos) break;  // VTK's parser reports it
    const std::string_view tag(xml.data() + at, end - at);
    line += static_cast<long>(std::count(xml.begin() + static_cast<std::ptrdiff_t>(counted),
                                         xml.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    counted = at;
    const std::string_view name = tag.substr(1, tag.find_first_of(" \t\r\n/") - 1);
    if (tag.substr(0, 2) == "</") {  // a closing tag
      if (std::find(kCellSections.begin(), kCellSections.end(), tag.substr(2)) !=
          kCellSections.end())
        cellSection = {};
      at = end;
      continue;
    }
    if (std::find(kCellSections.begin(), kCellSections.end(), name) != kCellSections.end())
      cellSection = name;
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
      if (const auto n = attribute(tag, "NumberOfComponents");
          n && !isWholeNumber(*n, 1, kMaxComponents))
        throw Error(file, line,
                    std::string(name) + " '" + arrayName + "': NumberOfComponents '" +
                        std::string(*n) + "' is not a whole number in [1, " +
                        std::to_string(kMaxComponents) + "]");
      if (const auto n = attribute(tag, "NumberOfTuples"); n && !isWholeNumber(*n, 0))
        throw Error(file, line,
                    std::string(name) + " '" + arrayName + "': NumberOfTuples '" + std::string(*n) +
                        "' is not a whole number >= 0");
    } else if (name == "Piece") {
      for (std::string_view size : {"NumberOfPoints", "NumberOfCells", "NumberOfVerts",
                                    "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        if (const auto n = attribute(tag, size); n && !isWholeNumber(*n, 0))
          throw Error(file, line,
                      "Piece: " + std::string(size) + " '" + std::string(*n) +
                          "' is not a whole number >= 0");
    }
    at = end;
  }
}

}  // namespace tetskin::detail
