// SPDX-License-Identifier: AGPL-3.0-or-later
// Faithful levels: every level build writes lies within its fidelity bound
// of the input as read, measured here by brute force; its boundary is closed
// and manifold and it has no flat element; a sheet's shell thickens as the
// level coarsens; an input that cannot be made faithful stops the build with
// the numbers and writes nothing, unless the user accepts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "ExpectError.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/DatasetBuild.h"
#include "tetskin/meshing/LevelFidelity.h"
#include "tetskin/meshing/MeshQuality.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/meshing/SurfaceRepair.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

const std::string kData = TETSKIN_TEST_DATA_DIR;

// The surface's triangles whose centroid lies above (or below) the height z.
SurfaceMesh cut(const SurfaceMesh& surface, double z, bool above) {
  std::vector<Eigen::Vector3i> kept;
  for (Index t = 0; t < surface.triangleCount(); ++t) {
    double centroid = 0;
    for (int k = 0; k < 3; ++k) centroid += surface.positions(surface.triangles(t, k), 2) / 3;
    if ((centroid > z) == above) kept.push_back(surface.triangles.row(t).transpose());
  }
  SurfaceMesh out;
  out.positions = surface.positions;
  out.triangles.resize(static_cast<Index>(kept.size()), 3);
  for (std::size_t t = 0; t < kept.size(); ++t)
    out.triangles.row(static_cast<Index>(t)) = kept[t].transpose();
  return out;
}

// An open cap of the unit sphere: a sheet, its rim a hole far wider than a
// quarter of its area, so the wrap makes it a shell.
SurfaceMesh openCap() {
  return cut(test::sphere({0, 0, 0}, 1.0, 24, 36), 0.3, true);
}

// A sphere with a hole cut at its top, as a scan's missing patch.
SurfaceMesh holedSphere(const Eigen::Vector3d& center, double radius) {
  return cut(test::sphere(center, radius, 14, 20), center.z() + 0.8 * radius, false);
}

// input -> level by brute force over every boundary triangle: {mean over
// the input's vertices weighted by area, max}.
std::pair<double, double> inputToLevel(const SurfaceMesh& input, const TetMesh& level) {
  const SurfaceMesh boundary = boundarySurface(level);
  std::vector<double> weight(static_cast<std::size_t>(input.vertexCount()), 0.0);
  for (Index t = 0; t < input.triangleCount(); ++t) {
    const double area = triangleArea(input.positions.row(input.triangles(t, 0)).transpose(),
                                     input.positions.row(input.triangles(t, 1)).transpose(),
                                     input.positions.row(input.triangles(t, 2)).transpose());
    for (int k = 0; k < 3; ++k) weight[static_cast<std::size_t>(input.triangles(t, k))] += area / 3;
  }
  double sum = 0, total = 0, max = 0;
  for (Index v = 0; v < input.vertexCount(); ++v) {
    if (weight[static_cast<std::size_t>(v)] == 0) continue;
    double best = std::numeric_limits<double>::infinity();
    for (Index t = 0; t < boundary.triangleCount(); ++t)
      best = std::min(
          best, closestPointOnTriangle(input.positions.row(v).transpose(),
                                       boundary.positions.row(boundary.triangles(t, 0)).transpose(),
                                       boundary.positions.row(boundary.triangles(t, 1)).transpose(),
                                       boundary.positions.row(boundary.triangles(t, 2)).transpose())
                    .squaredDistance);
    const double d = std::sqrt(best);
    sum += weight[static_cast<std::size_t>(v)] * d;
    total += weight[static_cast<std::size_t>(v)];
    max = std::max(max, d);
  }
  return {sum / total, max};
}

BuildOptions twoLevels(Index minElements, Index maxElements) {
  BuildOptions options;
  options.levels = 2;
  options.minElements = minElements;
  options.maxElements = maxElements;
  options.decimate = true;
  options.jobs = 2;
  return options;
}

// Every level: within its bound (measured here), closed and manifold, no
// flat element, the fidelity recorded as measured.
void expectFaithfulLevels(const SurfaceMesh& input, const BuildResult& r) {
  const Dataset& d = r.dataset;
  for (int k = 0; k < d.mesh.levelCount(); ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const TetMesh level = extractLevel(d.mesh, k);
    const auto& recorded = d.config.levels[static_cast<std::size_t>(k)].fidelity;
    ASSERT_TRUE(recorded.has_value());
    const double h = elementSize(level);
    EXPECT_NEAR(recorded->elementSize, h, 1e-12 * h);
    const auto [mean, max] = inputToLevel(input, level);
    EXPECT_NEAR(recorded->inputToLevelMean, mean, 1e-9 * (1 + mean));
    EXPECT_NEAR(recorded->inputToLevelMax, max, 1e-9 * (1 + max));
    EXPECT_LE(mean, kFidelityMeanShare * h);
    EXPECT_LE(max, kFidelityMaxShare * h);
    EXPECT_TRUE(recorded->faithful);
    const SurfaceMesh boundary = boundarySurface(level);
    EXPECT_TRUE(boundaryLoops(boundary).empty()) << "the level's boundary has gaps";
    EXPECT_EQ(nonManifoldEdgeCount(boundary), 0);
    double flattest = 1;
    for (Index e = 0; e < level.elementCount(); ++e)
      flattest = std::min(flattest, relativeVolume(level, e));
    EXPECT_GE(flattest, kFlatRelativeVolume);
  }
}

TEST(FaithfulLevels, TheHoledBunnyIsFaithfulAtEveryLevel) {
  const SurfaceMesh input = readObj(kData + "/bunny_holed.obj");
  const BuildResult r = buildDataset({{"bunny_holed.obj", input, ""}}, twoLevels(400, 2400));
  ASSERT_EQ(r.dataset.mesh.levelCount(), 2);
  expectFaithfulLevels(input, r);
}

TEST(FaithfulLevels, AnOpenSheetIsFaithfulAtEveryLevel) {
  const SurfaceMesh input = openCap();
  ASSERT_FALSE(boundaryLoops(input).empty());
  const BuildResult r = buildDataset({{"cap", input, ""}}, twoLevels(400, 2400));
  ASSERT_EQ(r.dataset.mesh.levelCount(), 2);
  expectFaithfulLevels(input, r);
  for (const LevelConfig& level : r.dataset.config.levels) {
    ASSERT_TRUE(level.source.wrap.has_value());
    EXPECT_GT(level.source.wrap->shellThickness, 0) << "a sheet becomes a shell";
  }
}

TEST(FaithfulLevels, ATwoPartSurfaceIsFaithfulAtEveryLevel) {
  const SurfaceMesh input =
      test::merge(holedSphere({0, 0, 0}, 1.0), holedSphere({3.0, 0.4, 0}, 0.7));
  const BuildResult r = buildDataset({{"two parts", input, ""}}, twoLevels(400, 2400));
  ASSERT_EQ(r.dataset.mesh.levelCount(), 2);
  expectFaithfulLevels(input, r);
}

// One level per target: the shell around a sheet is thicker for fewer
// elements, and each level stays within its bound.
TEST(FaithfulLevels, ASheetsShellThickensAsTheTargetShrinks) {
  const SurfaceMesh input = openCap();
  double previous = 0;
  for (Index target : {4000, 1500, 500}) {
    SCOPED_TRACE("target " + std::to_string(target));
    BuildOptions options = twoLevels(target, target);
    options.levels = 1;
    const BuildResult r = buildDataset({{"cap", input, ""}}, options);
    const LevelConfig& level = r.dataset.config.levels[0];
    ASSERT_TRUE(level.source.wrap.has_value());
    const double thickness = level.source.wrap->shellThickness;
    EXPECT_GT(thickness, previous);
    previous = thickness;
    expectFaithfulLevels(input, r);
  }
}

// Two holed spheres wrapped at an alpha as large as the whole: the wrap
// bridges the gap between them, so no level of 3000 elements follows them.
TEST(FaithfulLevels, AnInputThatCannotBeFaithfulStopsTheBuildUnlessAccepted) {
  const test::ScratchDir dir;
  const SurfaceMesh input = test::merge(holedSphere({0, 0, 0}, 1.0), holedSphere({3.0, 0, 0}, 1.0));
  writeObj(dir / "apart.obj", input);
  BuildOptions options = twoLevels(3000, 3000);
  options.levels = 1;
  options.decimate = false;
  options.wrap.alpha = 1.0;
  const std::string error = test::errorText(
      [&] { buildDatasetFiles({dir / "apart.obj"}, dir / "out" / "apart", options); });
  EXPECT_NE(error.find("level 0 (target 3000 elements) has no faithful candidate"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("lies off the input by"), std::string::npos) << error;
  EXPECT_NE(error.find("--wrap-offset"), std::string::npos) << error;
  EXPECT_NE(error.find("--accept-unfaithful"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "something was written";

  options.acceptUnfaithful = true;
  const DatasetBuild written =
      buildDatasetFiles({dir / "apart.obj"}, dir / "out" / "apart", options);
  const DatasetConfig config = readDatasetConfig(written.config);
  ASSERT_EQ(config.levels.size(), 1u);
  ASSERT_TRUE(config.levels[0].fidelity.has_value());
  const LevelFidelity& f = *config.levels[0].fidelity;
  EXPECT_FALSE(f.faithful);
  EXPECT_GT(f.inputToLevelMax, f.boundMax);
  const auto [mean, max] = inputToLevel(input, extractLevel(loadDataset(written.config).mesh, 0));
  EXPECT_NEAR(f.inputToLevelMax, max, 1e-9 * max);
  EXPECT_NEAR(f.inputToLevelMean, mean, 1e-9 * mean);
}

TEST(FaithfulLevels, ElementSizeIsTheRegularTetrahedronsEdge) {
  TetMesh regular;
  regular.nodes.resize(4, 3);
  regular.nodes << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;  // edge 2 sqrt(2)
  regular.elements.resize(1, 4);
  regular.elements << 0, 1, 2, 3;
  orientElementsPositively(regular);
  EXPECT_NEAR(elementSize(regular), 2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(relativeVolume(regular, 0), 1.0, 1e-12);
}

}  // namespace
}  // namespace tetskin
