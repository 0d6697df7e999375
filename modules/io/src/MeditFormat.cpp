// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/MeditFormat.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

using detail::TextLines;

// The sections read past: their record's token count (references included).
struct SkippedSection {
  const char* keyword;
  int tokens;
};
constexpr SkippedSection kSkipped[] = {{"edges", 3},
                                       {"quadrilaterals", 5},
                                       {"corners", 1},
                                       {"ridges", 1},
                                       {"requiredvertices", 1},
                                       {"requirededges", 1},
                                       {"requiredtriangles", 1},
                                       {"requiredquadrilaterals", 1},
                                       {"requiredtetrahedra", 1},
                                       {"normals", 3},
                                       {"normalatvertices", 2},
                                       {"tangents", 3},
                                       {"tangentatvertices", 2}};
// Volume elements other than tetrahedra, refused.
constexpr const char* kOtherVolumes[] = {"hexahedra", "prisms", "pyramids"};

std::string lower(std::string_view word) {
  std::string out(word);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Tokens across lines (a keyword's value may stand on its line or the next).
class Tokens {
 public:
  Tokens(std::string_view content, std::string sourceName)
      : lines_(content, std::move(sourceName), '#') {}

  // The next token; false at the end of the input.
  bool next(std::string_view& token) {
    while (index_ >= lines_.size()) {
      if (!lines_.next()) return false;
      index_ = 0;
    }
    token = lines_[index_++];
    return true;
  }
  std::string_view need(const std::string& what) {
    std::string_view token;
    if (!next(token)) lines_.fail("ends before " + what + " (truncated file?)");
    return token;
  }
  long long integer(const std::string& what) { return lines_.toInteger(need(what), what.c_str()); }
  double real(const std::string& what) { return lines_.toDouble(need(what), what.c_str()); }
  // A section's record count, which must fit in the rest of the file.
  long long count(const std::string& section, std::size_t tokensPerRecord) {
    const long long n = integer(section + " count");
    lines_.checkCount(n, 2 * tokensPerRecord, (section + " count").c_str());
    return n;
  }
  [[noreturn]] void fail(const std::string& what) const { lines_.fail(what); }

 private:
  TextLines lines_;
  std::size_t index_ = 0;
};

}  // namespace

MeditMesh parseMedit(std::string_view content, const std::string& sourceName) {
  Tokens tokens(content, sourceName);
  std::string_view token;
  if (!tokens.next(token) || lower(token) != "meshversionformatted")
    tokens.fail("is not a MEDIT mesh (.mesh): it does not start with MeshVersionFormatted");
  const long long version = tokens.integer("the format version");
  if (version < 1 || version > 4) tokens.fail("format version " + std::to_string(version));
  MeditMesh mesh;
  bool dimensionRead = false, vertices = false, ended = false;
  std::vector<std::array<int, 4>> tets;
  auto index = [&](const std::string& what, long long record) {
    const long long i = tokens.integer(what);
    if (i < 1 || i > mesh.vertices.rows())
      tokens.fail(what + " of record " + std::to_string(record + 1) + ": vertex " +
                  std::to_string(i) + " is out of range (1.." +
                  std::to_string(mesh.vertices.rows()) + ")");
    return static_cast<int>(i - 1);
  };
  while (!ended && tokens.next(token)) {
    const std::string keyword = lower(token);
    if (keyword == "dimension") {
      const long long d = tokens.integer("the dimension");
      if (d != 3) tokens.fail("dimension " + std::to_string(d) + ": a volume mesh has dimension 3");
      dimensionRead = true;
    } else if (keyword == "vertices") {
      if (!dimensionRead) tokens.fail("Vertices before Dimension");
      if (vertices) tokens.fail("a second Vertices section");
      const long long n = tokens.count("Vertices", 4);
      mesh.vertices.resize(n, 3);
      for (long long v = 0; v < n; ++v) {
        Eigen::RowVector3d p;
        for (int k = 0; k < 3; ++k) p[k] = tokens.real("vertex " + std::to_string(v + 1));
        if (const std::string problem = coordinateProblem(p); !problem.empty())
          tokens.fail("vertex " + std::to_string(v + 1) + " " + problem);
        mesh.vertices.row(v) = p;
        tokens.integer("vertex " + std::to_string(v + 1) + "'s reference");
      }
      vertices = true;
    } else if (keyword == "triangles" || keyword == "tetrahedra") {
      if (!vertices) tokens.fail(std::string(token) + " before Vertices");
      const int corners = keyword == "triangles" ? 3 : 4;
      const long long n = tokens.count(std::string(token), static_cast<std::size_t>(corners + 1));
      if (corners == 3) {
        const Index first = mesh.triangles.rows();
        mesh.triangles.conservativeResize(first + n, 3);
        for (long long t = 0; t < n; ++t) {
          for (int k = 0; k < 3; ++k) mesh.triangles(first + t, k) = index("triangle", t);
          tokens.integer("triangle's reference");
        }
      } else {
        for (long long t = 0; t < n; ++t) {
          std::array<int, 4> tet{};
          for (int& corner : tet) corner = index("tetrahedron", t);
          tokens.integer("tetrahedron's reference");
          tets.push_back(tet);
        }
      }
    } else if (keyword == "end") {
      ended = true;
    } else if (std::find_if(std::begin(kOtherVolumes), std::end(kOtherVolumes), [&](const char* k) {
                 return keyword == k;
               }) != std::end(kOtherVolumes)) {
      tokens.fail("has " + std::string(token) +
                  ": a dataset is made of tetrahedra (mesh with tetrahedra only)");
    } else {
      const auto skipped =
          std::find_if(std::begin(kSkipped), std::end(kSkipped),
                       [&](const SkippedSection& s) { return keyword == s.keyword; });
      if (skipped == std::end(kSkipped))
        tokens.fail("unknown keyword '" + std::string(token) +
                    "' (this reader takes Dimension, Vertices, Triangles, Tetrahedra, End, and "
                    "reads past Edges, Quadrilaterals, Corners, Ridges, Required..., Normals, "
                    "Tangents)");
      const long long n =
          tokens.count(std::string(token), static_cast<std::size_t>(skipped->tokens));
      for (long long r = 0; r < n; ++r)
        for (int k = 0; k < skipped->tokens; ++k) tokens.integer(std::string(token) + " record");
      mesh.skippedRecords += n;
    }
  }
  if (!vertices) tokens.fail("has no Vertices section");
  mesh.tetrahedra.resize(static_cast<Index>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.tetrahedra(static_cast<Index>(t), k) = tets[t][k];
  return mesh;
}

MeditMesh readMedit(const std::filesystem::path& path) {
  return parseMedit(detail::readWholeFile(path), path.string());
}

void writeMedit(const std::filesystem::path& path, const MeditMesh& mesh) {
  writeTextAtomically(path, [&](std::ostream& out) {
    char line[128];
    out << "MeshVersionFormatted 2\nDimension 3\n";
    out << "Vertices\n" << mesh.vertices.rows() << "\n";
    for (Index v = 0; v < mesh.vertices.rows(); ++v) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g 0\n", mesh.vertices(v, 0),
                    mesh.vertices(v, 1), mesh.vertices(v, 2));
      out << line;
    }
    if (mesh.triangles.rows() > 0) {
      out << "Triangles\n" << mesh.triangles.rows() << "\n";
      for (Index t = 0; t < mesh.triangles.rows(); ++t)
        out << mesh.triangles(t, 0) + 1 << ' ' << mesh.triangles(t, 1) + 1 << ' '
            << mesh.triangles(t, 2) + 1 << " 0\n";
    }
    if (mesh.tetrahedra.rows() > 0) {
      out << "Tetrahedra\n" << mesh.tetrahedra.rows() << "\n";
      for (Index t = 0; t < mesh.tetrahedra.rows(); ++t)
        out << mesh.tetrahedra(t, 0) + 1 << ' ' << mesh.tetrahedra(t, 1) + 1 << ' '
            << mesh.tetrahedra(t, 2) + 1 << ' ' << mesh.tetrahedra(t, 3) + 1 << " 1\n";
    }
    out << "End\n";
  });
}

}  // namespace tetskin
