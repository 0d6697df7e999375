// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// TetGen's text formats: .node, .ele, .face and .poly
// (https://wias-berlin.de/software/tetgen/fformats.html).
//
// `#` starts a comment. Item numbers start at 0 or 1, detected from the first
// item and required to be consecutive; indices in memory are always 0-based and
// `firstIndex` remembers the file's base so a round trip is exact. Attributes
// and boundary markers are kept.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/TetMesh.h"
#include "tetskin/core/Types.h"

namespace tetskin {

struct NodeFile {
  Points3 points;
  Eigen::MatrixXd attributes;  // points.rows() x attribute count
  std::vector<int> markers;    // empty, or one per point
  int firstIndex = 0;
};

struct EleFile {
  // 0-based node indices; 4 columns for linear tetrahedra, 10 for quadratic.
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> elements;
  Eigen::MatrixXd attributes;  // elements.rows() x attribute count (region attributes)
  int firstIndex = 0;

  // The four corner nodes of every element.
  Tetrahedra corners() const { return elements.leftCols<4>(); }
};

struct FaceFile {
  Triangles faces;           // 0-based node indices
  std::vector<int> markers;  // empty, or one per face
  int firstIndex = 0;
};

struct PolyFacet {
  std::vector<std::vector<int>> polygons;  // 0-based node indices
  Points3 holes;                           // one point inside each hole of the facet
  int marker = 0;
};

struct PolyRegion {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double attribute = 0.0;
  double maxVolume = -1.0;  // <= 0: no volume constraint
};

struct PolyFile {
  NodeFile nodes;                    // empty when the points live in a separate .node file
  bool nodesInSeparateFile = false;  // the .poly's node count was 0
  std::vector<PolyFacet> facets;
  bool facetMarkers = false;
  Points3 holes;
  std::vector<PolyRegion> regions;
};

// `sourceName` is used in error messages.
NodeFile parseNode(std::string_view content, const std::string& sourceName);
EleFile parseEle(std::string_view content, const std::string& sourceName);
FaceFile parseFace(std::string_view content, const std::string& sourceName);
// `nodeFirstIndex` is the index base of a separate .node file, if any; -1
// detects it from the .poly's own point list.
PolyFile parsePoly(std::string_view content, const std::string& sourceName,
                   int nodeFirstIndex = -1);

NodeFile readNode(const std::filesystem::path& path);
EleFile readEle(const std::filesystem::path& path);
FaceFile readFace(const std::filesystem::path& path);
// Loads the sibling .node file when the .poly has no points of its own.
PolyFile readPoly(const std::filesystem::path& path);

void writeNode(const std::filesystem::path& path, const NodeFile& file);
void writeEle(const std::filesystem::path& path, const EleFile& file);
void writeFace(const std::filesystem::path& path, const FaceFile& file);
void writePoly(const std::filesystem::path& path, const PolyFile& file);

// The two files of the .node/.ele pair that `either` names (a.node or
// a.ele: a.node and a.ele beside each other).
struct NodeElePaths {
  std::filesystem::path node, ele;
};
NodeElePaths nodeElePair(const std::filesystem::path& either);

// A .node/.ele pair as a tetrahedral mesh, validated (indices in range,
// finite coordinates; volumes are not checked here). `eleFirstIndex`, if
// given, gets the number the .ele file gives its first element (0 or 1).
TetMesh readTetMesh(const std::filesystem::path& nodePath, const std::filesystem::path& elePath,
                    int* eleFirstIndex = nullptr);

}  // namespace tetskin
