// SPDX-License-Identifier: AGPL-3.0-or-later
#include "PlyHeader.h"

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tetskin/core/Error.h"

namespace tetskin::detail {
namespace {

struct Element {
  std::string name;
  long line = 0;
  std::vector<std::string> scalars;
  std::vector<std::string> lists;
};

bool isPlyType(const std::string& t) {
  static const std::set<std::string> types = {
      "char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
      "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  return types.contains(t);
}

}  // namespace

void checkPlyHeader(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open for reading");
  const std::string file = path.string();
  std::string text;
  long line = 0;
  std::vector<Element> elements;
  bool ended = false;
  while (!ended && line < 10000 && std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string keyword;
    words >> keyword;
    if (line == 1) {
      if (keyword != "ply") throw Error(file, 1, "not a PLY file (no 'ply' magic)");
      continue;
    }
    if (keyword == "format") {
      std::string format, version;
      words >> format >> version;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        throw Error(file, line, "unknown PLY format '" + format + "'");
    } else if (keyword == "element") {
      Element e;
      long long count = -1;
      words >> e.name >> count;
      if (e.name.empty() || count < 0 || words.fail())
        throw Error(file, line, "malformed element declaration");
      e.line = line;
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty()) throw Error(file, line, "property before any element");
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType, itemType, name;
        words >> countType >> itemType >> name;
        if (!isPlyType(countType) || !isPlyType(itemType) || name.empty())
          throw Error(file, line, "malformed list property");
        elements.back().lists.push_back(name);
      } else {
        std::string name;
        words >> name;
        if (!isPlyType(type) || name.empty()) throw Error(file, line, "malformed property");
        elements.back().scalars.push_back(name);
      }
    } else if (keyword == "end_header") {
      ended = true;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      throw Error(file, line, "unknown PLY header line '" + keyword + "'");
    }
  }
  if (!ended) throw Error(file, line, "PLY header has no end_header");
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
  }
  if (!vertex) throw Error(file, 0, "PLY file has no vertex element");
  if (!vertex->lists.empty())
    throw Error(file, vertex->line, "the vertex element has a list property");
  for (const char* axis : {"x", "y", "z"}) {
    bool found = false;
    for (const auto& s : vertex->scalars) found = found || s == axis;
    if (!found) throw Error(file, vertex->line, std::string("vertices have no '") + axis + "'");
  }
  if (!face) throw Error(file, 0, "PLY file has no face element (a point cloud, not a surface)");
  bool indices = false;
  for (const auto& l : face->lists)
    indices = indices || l == "vertex_indices" || l == "vertex_index";
  if (!indices) throw Error(file, face->line, "faces have no vertex_indices list");
}

}  // namespace tetskin::detail
