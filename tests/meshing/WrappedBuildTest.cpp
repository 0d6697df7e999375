// SPDX-License-Identifier: AGPL-3.0-or-later
// build --wrap: the surfaces repair cannot close become datasets, measured
// against the input; the input stays the surface that is bound.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/LevelSelection.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/spatial/SurfaceDistance.h"

namespace tetskin {
namespace {

const std::string kData = TETSKIN_TEST_DATA_DIR;

BuildOptions smallLevels(WrapMode mode) {
  BuildOptions options;
  options.levels = 2;
  // (The holed bunny's faithful levels have 720 elements at the fewest:
  // its wrap's coarser decimations pinch its ears onto its head.)
  options.minElements = 800;
  options.maxElements = 3000;
  options.decimate = true;
  options.jobs = 2;
  options.wrap.mode = mode;
  return options;
}

BuildResult build(const std::string& name, const BuildOptions& options,
                  std::vector<std::string>* log = nullptr) {
  BuildEvents events;
  if (log) events.log = [log](const std::string& line) { log->push_back(line); };
  return buildDataset({{name, readObj(kData + "/" + name), ""}}, options, events);
}

bool logHas(const std::vector<std::string>& log, const std::string& start) {
  return std::any_of(log.begin(), log.end(),
                     [&](const std::string& l) { return l.rfind(start, 0) == 0; });
}

class BrokenInput : public testing::TestWithParam<const char*> {};

// Each broken input becomes a valid dataset under --wrap auto (positive
// elements, no unreferenced nodes, every level within 25% of its target),
// its levels record the wrap, and its default surface is the input as read.
TEST_P(BrokenInput, BecomesADatasetUnderWrapAuto) {
  const std::string name = GetParam();
  std::vector<std::string> log;
  const BuildOptions options = smallLevels(WrapMode::Auto);
  const BuildResult r = build(name, options, &log);
  const Dataset& d = r.dataset;
  ASSERT_EQ(d.mesh.levelCount(), 2);
  ASSERT_NO_THROW(validateLevels(d.mesh, name));
  const std::vector<double> targets =
      levelTargets(options.minElements, options.maxElements, options.levels);
  for (int k = 0; k < 2; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    const TetMesh level = extractLevel(d.mesh, k);
    EXPECT_NO_THROW(validateTetMesh(level, name, /*requirePositiveVolume=*/true));
    EXPECT_TRUE(unreferencedNodes(level).empty());
    EXPECT_NEAR(static_cast<double>(level.elementCount()), targets[static_cast<std::size_t>(k)],
                0.25 * targets[static_cast<std::size_t>(k)]);
    const std::optional<LevelWrap>& wrap = d.config.levels[static_cast<std::size_t>(k)].source.wrap;
    ASSERT_TRUE(wrap.has_value());
    EXPECT_GT(wrap->offset, 0.0);
    EXPECT_LE(wrap->inputToWrapMean, wrap->inputToWrapMax);
  }
  EXPECT_EQ(d.config.surface, std::filesystem::path(name));
  EXPECT_TRUE(logHas(log, "wrapping " + name)) << "no word of the wrap";
  EXPECT_TRUE(d.config.provenance["inputs"][0]["wrapped"].get<bool>());
}

// ... and is refused under --wrap never, as before the wrap existed.
TEST_P(BrokenInput, IsRefusedUnderWrapNever) {
  const std::string name = GetParam();
  const std::string error = test::errorText([&] { build(name, smallLevels(WrapMode::Never)); });
  EXPECT_NE(error.find(name), std::string::npos) << error;
  EXPECT_NE(error.find("--wrap auto"), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(ModelBuilder, BrokenInput,
                         testing::Values("bunny_holed.obj", "overlapping_spheres.obj",
                                         "soup_with_gaps.obj", "nonmanifold_fins.obj",
                                         "inverted_part.obj"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           std::string n = param.param;
                           return n.substr(0, n.find('.'));
                         });

// The distances build reports are those of the wrap it meshed, against the
// input as read: recomputed here by brute force for the finest level's
// input, the wrap itself, which build's log names by its triangle count.
TEST(ModelBuilder, WrapAlwaysWrapsAClosedInputAndMeasuresIt) {
  BuildOptions options = smallLevels(WrapMode::Always);
  options.decimate = false;
  options.levels = 1;
  options.minElements = options.maxElements = 1;  // the coarsest candidate
  const SurfaceMesh sphere = test::sphere({0, 0, 0}, 1.0, 12, 18);
  const BuildResult r = buildDataset({{"sphere", sphere, ""}}, options);
  const LevelWrap& w = *r.dataset.config.levels[0].source.wrap;
  const double diagonal = boundingBox(sphere).diagonal();
  EXPECT_NEAR(w.diagonal, diagonal, 1e-12);
  EXPECT_NEAR(w.alpha, options.wrap.alpha * diagonal, 1e-12);
  EXPECT_NEAR(w.offset, options.wrap.offset * diagonal, 1e-12);
  // The wrap again (CGAL is deterministic), measured by hand.
  const SurfaceMesh wrap = alphaWrap(sphere, w.alpha, w.offset, "sphere");
  const OneSidedDistance in = oneSidedDistance(sphere, wrap), out = oneSidedDistance(wrap, sphere);
  EXPECT_NEAR(w.inputToWrapMax, in.max, 1e-12);
  EXPECT_NEAR(w.inputToWrapMean, in.mean, 1e-12);
  EXPECT_NEAR(w.wrapToInputMax, out.max, 1e-12);
  EXPECT_NEAR(w.wrapToInputMean, out.mean, 1e-12);
  EXPECT_LE(w.wrapToInputMax, 1.05 * w.offset);  // a closed sphere: the offset all round
}

// The input with its holes stays the surface: bound to a wrapped level, it
// follows a rigid motion of the control mesh exactly.
TEST(ModelBuilder, TheHoledInputBoundToAWrappedLevelFollowsRigidMotion) {
  const BuildResult r = build("bunny_holed.obj", smallLevels(WrapMode::Auto));
  const SurfaceMesh input = readObj(kData + "/bunny_holed.obj");
  const MultiLevelTetMesh& mesh = r.dataset.mesh;
  const SurfaceBinding binding = bindSurface(input, mesh, mesh.finestLevel(), BindingOptions{});
  SurfaceDeformer deformer(input, binding, mesh.nodes);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(3, -1, 2);
  const Points3 moved = (mesh.nodes * rotation.transpose()).rowwise() + shift;
  Points3 positions, normals;
  deformer.deform(moved, positions, normals);
  const Points3 expected = (input.positions * rotation.transpose()).rowwise() + shift;
  const double diagonal = boundingBox(input).diagonal();
  EXPECT_LT((positions - expected).rowwise().norm().maxCoeff(), 1e-6 * diagonal);
}

TEST(ModelBuilder, AnOpenSheetBecomesAShellWithAWarningNamingItsThickness) {
  std::vector<std::string> log;
  BuildOptions options = smallLevels(WrapMode::Auto);
  options.levels = 1;
  options.minElements = options.maxElements = 1000;
  const BuildResult r = build("open_sheet.obj", options, &log);
  const LevelWrap& w = *r.dataset.config.levels[0].source.wrap;
  EXPECT_NEAR(w.shellThickness, 2 * w.offset, 0.5 * w.offset);
  EXPECT_TRUE(logHas(log,
                     "warning: open_sheet.obj is an open sheet, not a closed surface: it "
                     "became a shell body about "))
      << "no warning";
  EXPECT_NO_THROW(validateTetMesh(extractLevel(r.dataset.mesh, 0), "shell", true));
}

TEST(ModelBuilder, AnInputWithoutAreaIsRefusedWithTheReason) {
  for (WrapMode mode : {WrapMode::Auto, WrapMode::Always}) {
    const std::string error = test::errorText([&] { build("no_area.obj", smallLevels(mode)); });
    EXPECT_NE(error.find("no_area.obj"), std::string::npos) << error;
    EXPECT_NE(error.find("zero area"), std::string::npos) << error;
  }
}

// The wrap's parameters are fractions of the diagonal: outside (0, 1] is an error.
TEST(ModelBuilder, WrapParametersOutOfRangeAreRefused) {
  BuildOptions options = smallLevels(WrapMode::Always);
  options.wrap.alpha = 0;
  EXPECT_NE(test::errorText([&] {
              build("bunny_holed.obj", options);
            }).find("the wrap's alpha must lie in (0, 1], got 0"),
            std::string::npos);
  options.wrap.alpha = 0.02;
  options.wrap.offset = 2;
  EXPECT_NE(test::errorText([&] {
              build("bunny_holed.obj", options);
            }).find("the wrap's offset must lie in (0, 1], got 2"),
            std::string::npos);
}

}  // namespace
}  // namespace tetskin
