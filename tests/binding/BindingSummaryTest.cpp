// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tetskin/binding/BindingSummary.h"

namespace tetskin {
namespace {

// Ten vertices at distances 0, 0.1, .., 0.9; the even ones outside their
// triangles by their distance (vertex 0 on an edge: inside).
SurfaceBinding tenVertices() {
  SurfaceBinding b;
  b.level = 3;
  b.resize(10);
  for (Index v = 0; v < 10; ++v) {
    b.distance[v] = (v % 3 == 0 ? -0.1 : 0.1) * static_cast<double>(v);  // |d| counts
    b.minBarycentric[v] = v % 2 == 0 ? -0.1 * static_cast<double>(v) : 0.5;
  }
  return b;
}

TEST(BindingSummary, PercentilesSharesAndWorstVerticesAreKnown) {
  const BindingSummary s = summarizeBinding(tenVertices(), 2.0);
  EXPECT_EQ(s.vertices, 10);
  EXPECT_DOUBLE_EQ(s.diagonal, 2.0);
  EXPECT_DOUBLE_EQ(s.shareInside, 0.6);  // vertex 0 and the five odd ones
  // Over the diagonal: 0, 0.05, .., 0.45; the p-th percentile is the
  // ceil(p n)-th smallest.
  EXPECT_DOUBLE_EQ(s.distanceP50, 0.2);
  EXPECT_DOUBLE_EQ(s.distanceP90, 0.4);
  EXPECT_DOUBLE_EQ(s.distanceP99, 0.45);
  EXPECT_DOUBLE_EQ(s.distanceMax, 0.45);
  EXPECT_EQ(s.worstBarycentric, (std::vector<Index>{8, 6, 4, 2, 0}));
  EXPECT_EQ(s.worstDistance, (std::vector<Index>{9, 8, 7, 6, 5}));
  EXPECT_EQ(summarizeBinding(SurfaceBinding{}, 1.0).vertices, 0);  // empty: no percentiles
}

// The first line names the method and, where it matters, the offset: both
// offsets deform an embedded vertex alike (BindingAccuracyTest).
TEST(BindingSummary, TheFirstLineNamesTheOffsetExceptForEmbed) {
  SurfaceBinding b = tenVertices();
  const BindingSummary s = summarizeBinding(b, 1.0);
  auto firstLine = [&] {
    const std::string text = formatSummary(s, b);
    return text.substr(0, text.find('\n'));
  };
  b.method = BindingMethod::Seed;
  b.offset = OffsetMode::Displacement;
  EXPECT_EQ(firstLine(), "bound 10 vertices to level 3 (method seed, offset displacement)");
  b.method = BindingMethod::Embed;
  EXPECT_EQ(firstLine(), "bound 10 vertices to level 3 (method embed)");
  // Vertex 0's coordinate is -0 (-0.1 * 0): it reads 0.
  EXPECT_NE(formatSummary(s, b).find(
                "\n  most negative weight: v8 (-0.8) v6 (-0.6) v4 (-0.4) v2 (-0.2) v0 (0)\n"),
            std::string::npos)
      << formatSummary(s, b);
}

// The warning compares the 90th percentile (0.8 here, whatever the
// surface's diagonal) with the control mesh's diagonal.
TEST(BindingSummary, MisfitWarningComparesTheDistanceWithTheControlMeshsSize) {
  for (double surfaceDiagonal : {1.0, 2.0}) {
    const BindingSummary s = summarizeBinding(tenVertices(), surfaceDiagonal);
    EXPECT_EQ(misfitWarning(s, 10.0, "level 3"), "");  // 8%
    EXPECT_EQ(misfitWarning(s, 5.0, "level 3"),
              "a tenth of the vertices lie more than 16% of level 3's diagonal from its boundary: "
              "is the surface the dataset's object, placed and scaled as it is?");
  }
  // For a dataset level: that level's nodes give the diagonal (2 x 3 x 6:
  // 7), not the other levels'.
  auto tetrahedron = [](const Eigen::Vector3d& corner, const Eigen::Vector3d& size) {
    TetMesh t;
    t.nodes.resize(4, 3);
    t.nodes << corner.transpose(), corner.transpose() + Eigen::RowVector3d(size.x(), 0, 0),
        corner.transpose() + Eigen::RowVector3d(0, size.y(), 0),
        corner.transpose() + Eigen::RowVector3d(0, 0, size.z());
    t.elements.resize(1, 4);
    t.elements << 0, 1, 2, 3;
    return t;
  };
  MultiLevelTetMesh mesh;
  appendLevel(mesh, tetrahedron({0, 0, 0}, {100, 100, 100}));
  appendLevel(mesh, tetrahedron({5, 5, 5}, {2, 3, 6}));
  const BindingSummary s = summarizeBinding(tenVertices(), 1.0);
  EXPECT_EQ(misfitWarning(s, mesh, 1),
            "a tenth of the vertices lie more than 11% of level 1's diagonal from its boundary: "
            "is the surface the dataset's object, placed and scaled as it is?");
  EXPECT_EQ(misfitWarning(s, mesh, 0), "");
}

}  // namespace
}  // namespace tetskin
