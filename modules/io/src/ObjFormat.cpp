// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/ObjFormat.h"

#include <array>
#include <limits>
#include <map>
#include <unordered_set>
#include <vector>

#include "NumberFormat.h"
#include "PolygonTriangulation.h"
#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

// One face corner: 0-based indices, -1 where the corner has no such attribute.
struct Corner {
  int position = -1;
  int texcoord = -1;
  int normal = -1;
  auto operator<=>(const Corner&) const = default;
};

// Statements that carry nothing TetSkin uses; their arguments are not checked.
const std::unordered_set<std::string_view>& ignoredStatements() {
  static const std::unordered_set<std::string_view> names = {
      "o",      "g",      "s",         "usemtl", "mtllib",   "l",        "p",
      "vp",     "mg",     "lod",       "bevel",  "c_interp", "d_interp", "shadow_obj",
      "maplib", "usemap", "trace_obj", "cstype", "deg",      "bmat",     "step",
      "curv",   "curv2",  "surf",      "parm",   "trim",     "hole",     "scrv",
      "sp",     "end",    "con",       "call",   "csh"};
  return names;
}

class ObjParser {
 public:
  ObjParser(std::string_view content, const std::string& name) : lines_(content, name) {}

  SurfaceMesh parse(const ObjReadOptions& options) {
    while (lines_.next()) statement();
    if (triangles_.empty()) throw Error(lines_.sourceName(), 0, "contains no triangles");
    return assemble(options);
  }

 private:
  void statement() {
    const std::string_view keyword = lines_[0];
    if (keyword == "v") {
      // x y z [w] or x y z r g b (vertex colours, ignored)
      lines_.expectTokens(4, 7, "vertex");
      const std::array<double, 3> p = lines_.toPoint(1, "vertex");
      for (std::size_t k = 4; k < lines_.size(); ++k) lines_.toDouble(lines_[k], "vertex value");
      positions_.push_back(p);
    } else if (keyword == "vt") {
      lines_.expectTokens(2, 4, "texture coordinate");
      std::array<double, 2> t{lines_.toDouble(lines_[1], "texture coordinate"), 0.0};
      if (lines_.size() > 2) t[1] = lines_.toDouble(lines_[2], "texture coordinate");
      if (lines_.size() > 3) lines_.toDouble(lines_[3], "texture coordinate");
      texcoords_.push_back(t);
    } else if (keyword == "vn") {
      lines_.expectTokens(4, 4, "normal");
      std::array<double, 3> n{};
      for (int k = 0; k < 3; ++k) n[k] = lines_.toDouble(lines_[1 + k], "normal component");
      normals_.push_back(n);
    } else if (keyword == "f" || keyword == "fo") {
      face();
    } else if (!ignoredStatements().contains(keyword)) {
      lines_.fail("unknown OBJ statement '" + std::string(keyword) + "'");
    }
  }

  // Resolves a 1-based or negative (relative) OBJ index against `count` elements.
  int resolve(std::string_view token, std::size_t count, const char* what) const {
    const long long raw = lines_.toInteger(token, what);
    long long index = raw > 0 ? raw - 1 : static_cast<long long>(count) + raw;
    if (raw == 0 || index < 0 || index >= static_cast<long long>(count))
      lines_.fail(std::string(what) + " " + std::to_string(raw) + " is out of range (" +
                  std::to_string(count) + " defined so far)");
    return static_cast<int>(index);
  }

  Corner corner(std::string_view token) const {
    Corner c;
    const std::size_t slash1 = token.find('/');
    c.position = resolve(token.substr(0, slash1), positions_.size(), "vertex index");
    if (slash1 == std::string_view::npos) return c;
    const std::string_view rest = token.substr(slash1 + 1);
    const std::size_t slash2 = rest.find('/');
    const std::string_view vt = rest.substr(0, slash2);
    if (!vt.empty()) c.texcoord = resolve(vt, texcoords_.size(), "texture coordinate index");
    if (slash2 != std::string_view::npos) {
      const std::string_view vn = rest.substr(slash2 + 1);
      if (vn.empty() || vn.find('/') != std::string_view::npos)
        lines_.fail("malformed face corner '" + std::string(token) + "'");
      c.normal = resolve(vn, normals_.size(), "normal index");
    } else if (vt.empty()) {
      lines_.fail("malformed face corner '" + std::string(token) + "'");
    }
    return c;
  }

  void face() {
    if (lines_.size() < 4)
      lines_.fail("a face needs at least 3 vertices, found " + std::to_string(lines_.size() - 1));
    std::vector<Corner> polygon;
    polygon.reserve(lines_.size() - 1);
    for (std::size_t k = 1; k < lines_.size(); ++k) polygon.push_back(corner(lines_[k]));
    detail::appendTriangles(
        polygon,
        [&](const Corner& c) {
          const auto& p = positions_[static_cast<std::size_t>(c.position)];
          return Eigen::Vector3d(p[0], p[1], p[2]);
        },
        triangles_);
  }

  SurfaceMesh assemble(const ObjReadOptions& options) const {
    bool allTex = options.keepAttributes && !texcoords_.empty();
    bool allNormals = options.keepAttributes && !normals_.empty();
    for (const auto& t : triangles_)
      for (const Corner& c : t) {
        allTex = allTex && c.texcoord >= 0;
        allNormals = allNormals && c.normal >= 0;
      }
    SurfaceMesh mesh;
    if (!allTex && !allNormals) {
      mesh.positions.resize(static_cast<Index>(positions_.size()), 3);
      for (std::size_t v = 0; v < positions_.size(); ++v)
        for (int k = 0; k < 3; ++k) mesh.positions(static_cast<Index>(v), k) = positions_[v][k];
      mesh.triangles.resize(static_cast<Index>(triangles_.size()), 3);
      for (std::size_t t = 0; t < triangles_.size(); ++t)
        for (int k = 0; k < 3; ++k)
          mesh.triangles(static_cast<Index>(t), k) = triangles_[t][k].position;
      return mesh;
    }
    // One output vertex per distinct (position, texcoord, normal) in use; a
    // position never used by a face keeps one vertex of its own so vertex
    // numbering stays close to the file's, with the texture coordinate and
    // normal of its own number where the file has that many (as a file
    // written one per vertex has: ours, read back, keeps them), else the
    // first. (fuzz_obj found the first alone broke the round trip.)
    std::map<Corner, int> vertexOf;
    std::vector<Corner> vertices;
    std::vector<char> positionUsed(positions_.size(), 0);
    auto key = [&](Corner c) {
      if (!allTex) c.texcoord = -1;
      if (!allNormals) c.normal = -1;
      return c;
    };
    for (const auto& t : triangles_)
      for (const Corner& c : t) positionUsed[static_cast<std::size_t>(c.position)] = 1;
    mesh.triangles.resize(static_cast<Index>(triangles_.size()), 3);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Corner c = key(triangles_[t][k]);
        auto [it, inserted] = vertexOf.try_emplace(c, static_cast<int>(vertices.size()));
        if (inserted) vertices.push_back(c);
        mesh.triangles(static_cast<Index>(t), k) = it->second;
      }
    for (std::size_t p = 0; p < positions_.size(); ++p)
      if (!positionUsed[p]) {
        const auto own = [p](std::size_t count) { return p < count ? static_cast<int>(p) : 0; };
        vertices.push_back(
            Corner{static_cast<int>(p), own(texcoords_.size()), own(normals_.size())});
      }
    const Index n = static_cast<Index>(vertices.size());
    mesh.positions.resize(n, 3);
    if (allTex) mesh.texcoords.resize(n, 2);
    if (allNormals) mesh.normals.resize(n, 3);
    for (Index v = 0; v < n; ++v) {
      const Corner& c = vertices[static_cast<std::size_t>(v)];
      for (int k = 0; k < 3; ++k) mesh.positions(v, k) = positions_[c.position][k];
      if (allTex)
        for (int k = 0; k < 2; ++k) mesh.texcoords(v, k) = texcoords_[c.texcoord][k];
      if (allNormals)
        for (int k = 0; k < 3; ++k) mesh.normals(v, k) = normals_[c.normal][k];
    }
    return mesh;
  }

  detail::TextLines lines_;
  std::vector<std::array<double, 3>> positions_;
  std::vector<std::array<double, 2>> texcoords_;
  std::vector<std::array<double, 3>> normals_;
  std::vector<std::array<Corner, 3>> triangles_;
};

}  // namespace

SurfaceMesh parseObj(std::string_view content, const std::string& sourceName,
                     const ObjReadOptions& options) {
  return ObjParser(content, sourceName).parse(options);
}

SurfaceMesh readObj(const std::filesystem::path& path, const ObjReadOptions& options) {
  const std::string content = detail::readWholeFile(path);
  return parseObj(content, path.string(), options);
}

void writeObj(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  validateSurface(mesh, path.string());
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "# written by TetSkin\n";
    auto row = [&](const char* keyword, const auto& matrix, Index r) {
      out << keyword;
      for (Index k = 0; k < matrix.cols(); ++k) {
        out << ' ';
        detail::writeDouble(out, matrix(r, k));
      }
      out << '\n';
    };
    for (Index v = 0; v < mesh.vertexCount(); ++v) row("v", mesh.positions, v);
    for (Index v = 0; v < mesh.texcoords.rows(); ++v) row("vt", mesh.texcoords, v);
    for (Index v = 0; v < mesh.normals.rows(); ++v) row("vn", mesh.normals, v);
    for (Index t = 0; t < mesh.triangleCount(); ++t) {
      out << 'f';
      for (int k = 0; k < 3; ++k) {
        const int id = mesh.triangles(t, k) + 1;
        out << ' ' << id;
        if (mesh.hasTexcoords() && mesh.hasNormals())
          out << '/' << id << '/' << id;
        else if (mesh.hasTexcoords())
          out << '/' << id;
        else if (mesh.hasNormals())
          out << "//" << id;
      }
      out << '\n';
    }
  });
}

}  // namespace tetskin
