// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <tuple>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/LevelSelection.h"
#include "tetskin/meshing/Meshers.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin {
namespace {

void expectValidDataset(const Dataset& d) {
  ASSERT_NO_THROW(validateLevels(d.mesh, "built"));
  for (int k = 0; k < d.mesh.levelCount(); ++k) {
    const TetMesh level = extractLevel(d.mesh, k);
    EXPECT_NO_THROW(validateTetMesh(level, "level", /*requirePositiveVolume=*/true));
    EXPECT_TRUE(unreferencedNodes(level).empty()) << "level " << k;
  }
}

TEST(ModelBuilder, BundledBunnyGivesTheRequestedLevels) {
  std::vector<SurfaceInput> inputs = {
      {"bunny.obj", readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj"), ""}};
  BuildOptions options;
  options.decimate = true;
  options.levels = 3;
  options.minElements = 600;
  options.maxElements = 12000;
  options.jobs = 2;
  std::vector<std::string> log;
  const BuildResult r =
      buildDataset(inputs, options, {[&](const std::string& l) { log.push_back(l); }, {}, {}});
  const Dataset& d = r.dataset;
  ASSERT_EQ(d.mesh.levelCount(), 3);
  const double targets[3] = {600, 2683.28, 12000};
  for (int k = 0; k < 3; ++k) {
    const double count =
        static_cast<double>(d.mesh.levels[static_cast<std::size_t>(k)].elementCount);
    EXPECT_NEAR(count, targets[k], 0.25 * targets[k]) << "level " << k;
  }
  EXPECT_LT(d.mesh.levels[0].elementCount, d.mesh.levels[1].elementCount);
  EXPECT_LT(d.mesh.levels[1].elementCount, d.mesh.levels[2].elementCount);
  expectValidDataset(d);
  EXPECT_EQ(d.config.surface, std::filesystem::path("bunny.obj"));
  EXPECT_EQ(d.config.levels[0].source.mesher, "tetgen");
  EXPECT_GT(d.config.levels[2].statistics.at("min_dihedral_deg"), 0.0);
  EXPECT_EQ(d.config.provenance["candidates"].size(), r.candidates.size());
  // The input and its decimations, 5 qualities each, meshed or skipped as
  // finer than one above the largest target.
  EXPECT_GE(r.candidates.size() + r.skippedCandidates, 25u);
  EXPECT_GT(r.skippedCandidates, 0u);
}

// A decimated cylinder's surface gives TetGen slivers at every quality:
// build says so for the level, and how to avoid them; Netgen's level of
// the same surface has none, and no warning.
TEST(ModelBuilder, WarnsOfSliversWhereTetGenMakesThem) {
  const std::string file = std::string(TETSKIN_SOURCE_DIR) + "/tests/data/decimated_cylinder.obj";
  std::vector<SurfaceInput> inputs = {{"decimated_cylinder.obj", readObj(file), ""}};
  BuildOptions options;
  options.levels = 1;
  options.minElements = options.maxElements = 4000;
  options.jobs = 2;
  auto sliverLines = [](const std::vector<std::string>& log) {
    std::vector<std::string> lines;
    for (const std::string& line : log)
      if (line.find("slivers") != std::string::npos) lines.push_back(line);
    return lines;
  };
  std::vector<std::string> log;
  const BuildEvents events{[&](const std::string& l) { log.push_back(l); }, {}, {}};
  const BuildResult tetgen = buildDataset(inputs, options, events);
  const double worst = tetgen.dataset.config.levels[0].statistics.at("min_dihedral_deg");
  EXPECT_LT(worst, 1.0);
  const std::vector<std::string> warned = sliverLines(log);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_EQ(warned[0].rfind("warning: level 0 has slivers (smallest dihedral angle ", 0), 0u)
      << warned[0];
  if (netgenAvailable()) {
    EXPECT_NE(warned[0].find("; --mesher netgen remeshes the surface"), std::string::npos)
        << warned[0];
    log.clear();
    options.mesher = MesherKind::Netgen;
    const BuildResult netgen = buildDataset(inputs, options, events);
    EXPECT_GT(netgen.dataset.config.levels[0].statistics.at("min_dihedral_deg"), 10.0);
    EXPECT_TRUE(sliverLines(log).empty()) << sliverLines(log).front();
  }
}

TEST(ModelBuilder, SearchOrderIsFinestInputAndBestQualityFirst) {
  const SurfaceMesh fine = test::box({0, 0, 0}, {1, 1, 1});
  std::vector<SurfaceInput> inputs = {{"a", fine, ""},
                                      {"b", test::box({0, 0, 0}, {1.1, 1.1, 1.1}), ""}};
  BuildOptions options;
  options.levels = 1;
  options.minElements = options.maxElements = 1000000;  // (above every candidate: none skipped)
  options.qualities = {2.0, 1.4};
  const BuildResult r = buildDataset(inputs, options);
  ASSERT_EQ(r.candidates.size(), 4u);
  EXPECT_EQ(r.candidates[0].label, "q1.4");
  EXPECT_EQ(r.candidates[1].label, "q2");
  // Equal triangle counts keep the given order.
  EXPECT_EQ(r.candidates[0].input, "a");
  EXPECT_EQ(r.candidates[2].input, "b");
}

// (--wrap never: what build did before the wrap; WrappedBuildTest.cpp has
// the wrap.)
// The targets drive the work: candidates run coarse to fine, and once one
// is above the largest target, those of inputs with at least as many
// triangles at a bound no looser are skipped; the rest keep the search
// order. Two boxes of 12 triangles give 6 elements at q2 and more at q1.1:
// a target of 1 leaves one candidate, q2 of the input given first.
TEST(ModelBuilder, CandidatesFinerThanOneAboveTheLargestTargetAreSkipped) {
  std::vector<SurfaceInput> inputs = {{"a", test::box({0, 0, 0}, {1, 1, 1}), ""},
                                      {"b", test::box({0, 0, 0}, {1.1, 1.1, 1.1}), ""}};
  BuildOptions options;
  options.levels = 1;
  options.minElements = options.maxElements = 1;
  options.qualities = {2.0, 1.1};
  std::vector<std::string> log;
  const BuildResult r =
      buildDataset(inputs, options, {[&](const std::string& l) { log.push_back(l); }, {}, {}});
  ASSERT_EQ(r.candidates.size(), 1u);
  EXPECT_EQ(r.skippedCandidates, 3u);
  EXPECT_EQ(r.candidates[0].label, "q2");
  EXPECT_NE(std::find(log.begin(), log.end(),
                      "skipped 3 of 4 candidates: finer than one already above the largest "
                      "target (1 elements)"),
            log.end());
}

// Which candidates a build skips does not depend on which of its parallel
// jobs ended first: the bunny's build with 1 job and with 3 gives the same
// candidates and levels.
TEST(ModelBuilder, TheCandidatesDoNotDependOnTheJobs) {
  std::vector<std::vector<std::pair<std::string, Index>>> candidates;
  std::vector<std::vector<Index>> levels;
  for (int jobs : {1, 3}) {
    BuildOptions options;
    options.decimate = true;
    options.jobs = jobs;
    const BuildResult r = buildDataset(
        {{"bunny.obj", readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj"), ""}},
        options);
    candidates.emplace_back();
    for (const CandidateReport& c : r.candidates)
      candidates.back().emplace_back(c.input + " " + c.label, c.elements);
    levels.emplace_back();
    for (const LevelRange& level : r.dataset.mesh.levels) levels.back().push_back(level.elementCount);
  }
  EXPECT_EQ(candidates[0], candidates[1]);
  EXPECT_EQ(levels[0], levels[1]);
}

TEST(ModelBuilder, UnrepairableInputsAreSkippedOrReported) {
  SurfaceMesh holey = test::box({0, 0, 0}, {1, 1, 1});
  holey.triangles.conservativeResize(10, 3);
  BuildOptions never;
  never.wrap.mode = WrapMode::Never;
  EXPECT_THROW(buildDataset({{"holey", holey, ""}}, never), Error);
  std::vector<std::string> log;
  BuildOptions options = never;
  options.levels = 1;
  const BuildResult r =
      buildDataset({{"holey", holey, ""}, {"box", test::box({0, 0, 0}, {1, 1, 1}), ""}}, options,
                   {[&](const std::string& l) { log.push_back(l); }, {}, {}});
  EXPECT_EQ(r.dataset.mesh.levelCount(), 1);
  EXPECT_EQ(r.dataset.config.levels[0].source.input, "box");
  bool skipped = false;
  for (const std::string& line : log) skipped = skipped || line.find("skipping input: holey") == 0;
  EXPECT_TRUE(skipped);
}

TEST(ModelBuilder, OverlappingPartsAreWarnedAboutAndTheirVolumesRecorded) {
  const SurfaceMesh cubes =
      test::merge(test::box({0, 0, 0}, {1, 1, 1}), test::box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  BuildOptions options;
  options.levels = 1;
  options.qualities = {2.0};
  std::vector<std::string> log;
  const BuildResult r = buildDataset({{"cubes.obj", cubes, ""}}, options,
                                     {[&](const std::string& l) { log.push_back(l); }, {}, {}});
  const std::string warning = "warning: cubes.obj: collapsing ";
  EXPECT_EQ(std::count_if(log.begin(), log.end(),
                          [&](const std::string& l) { return l.rfind(warning, 0) == 0; }),
            1);
  const nlohmann::json& repair = r.dataset.config.provenance["inputs"][0]["repair"];
  EXPECT_DOUBLE_EQ(repair["volume_before_collapse"].get<double>(), 2.0);
  EXPECT_LT(repair["volume_after_collapse"].get<double>(), 1.98);
  // A clean input records no volumes.
  const BuildResult box = buildDataset({{"box", test::box({0, 0, 0}, {1, 1, 1}), ""}}, options);
  EXPECT_FALSE(
      box.dataset.config.provenance["inputs"][0]["repair"].contains("volume_before_collapse"));
}

// Levels of detail of one object share most of their bounding box; another
// object, or this one moved or in other units, is refused before any work.
TEST(ModelBuilder, AnInputThatIsNotALevelOfDetailOfTheFinestIsRefused) {
  // (Equal triangle counts keep the given order: the first is the finest.)
  const SurfaceMesh fine = test::box({0, 0, 0}, {1, 1, 1});
  BuildOptions options;
  options.levels = 1;
  options.qualities = {2.0};
  // Slightly shrunk and moved, as a decimation may leave it: accepted.
  EXPECT_NO_THROW(buildDataset(
      {{"fine.obj", fine, ""}, {"near.obj", test::box({0.02, 0, 0.01}, {0.97, 1, 1}), ""}},
      options));
  for (const auto& [min, max, share] :
       {std::tuple{Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(11, 1, 1), "0"},
        std::tuple{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 2, 2), "12.5"},  // other units
        std::tuple{Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(1.5, 1, 1), "33.3"}}) {
    std::vector<std::string> log;
    try {
      buildDataset({{"fine.obj", fine, ""}, {"other.obj", test::box(min, max), ""}}, options,
                   {[&](const std::string& l) { log.push_back(l); }, {}, {}});
      ADD_FAILURE() << "accepted " << max.transpose();
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), "other.obj");
      EXPECT_EQ(e.message().rfind(std::string("is not a level of detail of fine.obj: their "
                                              "bounding boxes share ") +
                                      share + "% of the volume they span together",
                                  0),
                0u)
          << e.message();
    }
    EXPECT_TRUE(log.empty());  // not even repaired
  }
}

TEST(ModelBuilder, TheSameSurfaceTwiceIsRefusedBeforeAnyMeshing) {
  const SurfaceMesh box = test::box({0, 0, 0}, {1, 1, 1});
  SurfaceMesh moved = box;
  moved.positions(0, 0) += 1e-9;  // a different surface, if barely
  std::vector<std::string> log;
  try {
    buildDataset({{"a.obj", box, ""}, {"b.obj", moved, ""}, {"copy.obj", box, ""}}, BuildOptions{},
                 {[&](const std::string& l) { log.push_back(l); }, {}, {}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "copy.obj");
    EXPECT_STREQ(e.what(),
                 "copy.obj: is the same surface as the input a.obj; each input is a level of "
                 "detail of its own");
  }
  EXPECT_TRUE(log.empty());  // not even repaired
}

TEST(ModelBuilder, NetgenBuildsLevels) {
  BuildOptions options;
  options.mesher = MesherKind::Netgen;
  options.levels = 2;
  options.minElements = 50;
  options.maxElements = 2000;
  options.jobs = 2;
  try {
    const BuildResult r = buildDataset({{"box", test::box({0, 0, 0}, {2, 1, 1}), ""}}, options);
    // The five presets, finest first, but for those finer than one above
    // the largest target (here "very fine": "fine" has more than 2000).
    EXPECT_EQ(r.candidates.size() + r.skippedCandidates, 5u);
    EXPECT_GE(r.skippedCandidates, 1u);
    EXPECT_EQ(r.candidates.back().label, "very coarse");
    for (std::size_t c = 1; c < r.candidates.size(); ++c)
      EXPECT_GT(r.candidates[c - 1].quality, r.candidates[c].quality);
    expectValidDataset(r.dataset);
  } catch (const Error& e) {
    if (std::string(e.what()).find("without Netgen") == std::string::npos) throw;
    GTEST_SKIP() << e.what();
  }
}

// A box meshes into a few elements at every quality (6 to 16 for this one),
// so no level can be near
// its target; with sizing, each is (the targets 600, 2683 and 12000 were
// met within 10% when this was written; 25% leaves room for another TetGen
// build). The sized levels are recorded with their bound.
TEST(ModelBuilder, SizingMeetsTargetsThatNoQualityCan) {
  const SurfaceMesh box = test::box({0, 0, 0}, {1, 2, 3});
  BuildOptions options;
  options.levels = 3;
  options.minElements = 600;
  options.maxElements = 12000;
  options.jobs = 2;
  std::vector<std::string> log;
  const BuildEvents events{[&](const std::string& l) { log.push_back(l); }, {}, {}};
  const BuildResult plain = buildDataset({{"box", box, ""}}, options, events);
  for (const auto& level : plain.dataset.mesh.levels) EXPECT_LT(level.elementCount, 100);
  EXPECT_NE(log.back().find("--size-to-targets"), std::string::npos) << log.back();

  options.sizeToTargets = true;
  log.clear();
  const BuildResult sized = buildDataset({{"box", box, ""}}, options, events);
  const Dataset& d = sized.dataset;
  ASSERT_EQ(d.mesh.levelCount(), 3);
  const auto targets = levelTargets(600, 12000, 3);
  for (std::size_t k = 0; k < 3; ++k) {
    const double count = static_cast<double>(d.mesh.levels[k].elementCount);
    EXPECT_NEAR(count, targets[k], 0.25 * targets[k]) << "level " << k;
    EXPECT_GT(d.config.levels[k].source.sizeBound, 0.0) << "level " << k;
    const CandidateReport& chosen = sized.candidates[static_cast<std::size_t>(sized.chosen[k])];
    EXPECT_EQ(chosen.sizeBound, d.config.levels[k].source.sizeBound);
    EXPECT_NE(chosen.label.find(" a"), std::string::npos) << chosen.label;
  }
  for (const std::string& line : log) EXPECT_EQ(line.find("warning"), std::string::npos) << line;
  expectValidDataset(d);
  // The quality candidates come first, in their search order, then the sized ones.
  EXPECT_EQ(sized.candidates[0].label, "q1.2");
  EXPECT_EQ(sized.candidates[4].sizeBound, 0.0);
  EXPECT_GT(sized.candidates[5].sizeBound, 0.0);
  EXPECT_TRUE(d.config.provenance["options"]["size_to_targets"].get<bool>());
}

// Sizing leaves alone what the qualities already meet, and says which
// targets no bound can reach: TetGen keeps the surface's triangles, so a
// surface that alone needs more elements than a target cannot be sized down.
TEST(ModelBuilder, SizingSkipsMetTargetsAndNamesUnreachableOnes) {
  const SurfaceMesh bunny = readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj");
  BuildOptions options;
  options.levels = 1;
  options.qualities = {2.0};
  options.sizeToTargets = true;
  options.jobs = 2;
  std::vector<std::string> log;
  const BuildEvents events{[&](const std::string& l) { log.push_back(l); }, {}, {}};
  options.minElements = options.maxElements = 100;
  const BuildResult tooFew = buildDataset({{"bunny", bunny, ""}}, options, events);
  EXPECT_EQ(tooFew.candidates.size(), 1u);
  bool named = false;
  for (const std::string& line : log)
    named = named || line.find("sizing: no input can be meshed to about 100 elements") == 0;
  EXPECT_TRUE(named);

  options.minElements = options.maxElements = tooFew.candidates[0].elements;
  const BuildResult met = buildDataset({{"bunny", bunny, ""}}, options, events);
  EXPECT_EQ(met.candidates.size(), 1u);  // no sizing run
  EXPECT_EQ(met.dataset.config.levels[0].source.sizeBound, 0.0);
}

TEST(ModelBuilder, NetgenSizingMeetsATargetItsPresetsMiss) {
  if (!netgenAvailable()) GTEST_SKIP() << "built without Netgen";
  BuildOptions options;
  options.mesher = MesherKind::Netgen;
  options.levels = 1;
  options.minElements = options.maxElements = 5000;  // the presets give 30-600 on this box
  options.sizeToTargets = true;
  options.jobs = 2;
  const BuildResult r = buildDataset({{"box", test::box({0, 0, 0}, {2, 1, 1}), ""}}, options);
  const double count = static_cast<double>(r.dataset.mesh.levels[0].elementCount);
  EXPECT_NEAR(count, 5000, 0.5 * 5000);
  EXPECT_GT(r.dataset.config.levels[0].source.sizeBound, 0.0);
  EXPECT_EQ(r.dataset.config.levels[0].source.quality, 2.0);  // the moderate preset
  expectValidDataset(r.dataset);
}

// Real models written by other tools: each gives a valid dataset or a clear
// error; never a crash, a hang or another kind of exception.
TEST(ModelBuilder, AssimpCorpusGivesDatasetsOrClearErrors) {
  const std::filesystem::path corpus = "/usr/share/assimp/models/OBJ";
  if (!std::filesystem::is_directory(corpus)) GTEST_SKIP() << "assimp-testmodels not installed";
  int built = 0, refused = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    if (entry.path().extension() != ".obj") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      SurfaceMesh mesh = readSurface(entry.path());
      BuildOptions options;
      options.levels = 1;
      options.qualities = {2.0};
      options.timeoutSeconds = 60;
      options.jobs = 2;
      const BuildResult r = buildDataset({{entry.path().filename().string(), mesh, ""}}, options);
      expectValidDataset(r.dataset);
      ++built;
    } catch (const Error& e) {
      EXPECT_FALSE(std::string(e.what()).empty());
      ++refused;
    }
  }
  std::printf("assimp OBJ corpus: %d built, %d refused with an error\n", built, refused);
  EXPECT_GT(built, 0);
}

// Netgen's own example geometries (Debian's netgen-doc) through both meshers.
TEST(ModelBuilder, NetgenExampleModelsGiveDatasetsOrClearErrors) {
  const std::filesystem::path examples = "/usr/share/doc/netgen/examples";
  if (!std::filesystem::is_directory(examples)) GTEST_SKIP() << "netgen-doc not installed";
  int built = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    if (entry.path().extension() != ".stl") continue;
    for (MesherKind mesher : {MesherKind::TetGen, MesherKind::Netgen}) {
      SCOPED_TRACE(entry.path().string());
      BuildOptions options;
      options.mesher = mesher;
      options.levels = 2;
      options.minElements = 500;
      options.maxElements = 5000;
      options.qualities = {2.0, 1.6};
      options.timeoutSeconds = 120;
      options.jobs = 2;
      try {
        const BuildResult r =
            buildDataset({{entry.path().string(), readSurface(entry.path()), ""}}, options);
        expectValidDataset(r.dataset);
        ++built;
      } catch (const Error& e) {
        if (std::string(e.what()).find("without Netgen") != std::string::npos) continue;
        EXPECT_FALSE(std::string(e.what()).empty());
      }
    }
  }
  EXPECT_GE(built, 2);  // hinge.stl and part1.stl mesh with both meshers here
}

}  // namespace
}  // namespace tetskin
