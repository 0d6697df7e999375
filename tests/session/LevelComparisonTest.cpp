// SPDX-License-Identifier: AGPL-3.0-or-later
// The comparison of levels (issue #55): two runs of one level agree, a
// rigid motion deforms the surface alike on any two levels, the series
// and table hold what they say, and bad input is refused by name.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "ExpectError.h"
#include "Frames.h"
#include "SampleData.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/session/LevelComparison.h"
#include "tetskin/session/SceneFile.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

// One upright block (y up) at two resolutions.
MultiLevelTetMesh twoLevels() {
  MultiLevelTetMesh mesh;
  appendLevel(mesh, test::tetGrid(2, 4, 2, {0.2, 0.4, 0.2}));
  appendLevel(mesh, test::tetGrid(4, 8, 4, {0.2, 0.4, 0.2}));
  return mesh;
}

// A skin around the block, a little off its faces.
SurfaceMesh skin() {
  return test::sphere({0.1, 0.2, 0.1}, 0.12, 10, 14);
}

RunSpec wobble(int level) {
  RunSpec spec;
  spec.level = level;
  spec.options.timeStep = 0.01;
  spec.options.material.youngsModulus = 2e4;
  // (CG alone: the automatic choice times its solvers, and two runs could
  // take other solvers and differ by the tolerance.)
  spec.options.solver = SolverKind::ConjugateGradient;
  spec.scenario = "wobble";
  spec.datasetName = "block";
  return spec;
}

TEST(LevelComparison, TwoRunsOfOneLevelGiveNoError) {
  const MultiLevelTetMesh mesh = twoLevels();
  LevelComparison comparison(mesh, skin(), {wobble(1), wobble(1)}, 0, "block.json");
  ASSERT_TRUE(comparison.simulated());
  comparison.compare();
  for (int i = 0; i < 6; ++i) {
    comparison.advance();
    comparison.compare();
  }
  ASSERT_EQ(comparison.frames().size(), 7u);
  EXPECT_EQ(comparison.frames().back().steps, 6);
  EXPECT_NEAR(comparison.frames().back().time, 0.06, 1e-12);
  // The surface moved, alike in both.
  EXPECT_GT((comparison.surface(1).deformed->positions - skin().positions).norm(), 1e-6);
  const ErrorSpread e = comparison.overall(1);
  EXPECT_EQ(e.distance.max, 0);
  EXPECT_EQ(e.angle.max, 0);
  EXPECT_GT(comparison.meanStepSeconds(1), 0);
}

// Levels that move alike deform the surface alike: a rigid motion of each
// level (recorded as runs) moves the surface rigidly whatever level it is
// bound to, as the normal offset is exact under rigid motion. What is left
// is rounding (the binding's weights and offsets reproduce the rest surface
// to about 1e-15 of its size).
TEST(LevelComparison, ARigidMotionGivesNoErrorBetweenLevels) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = twoLevels();
  for (int level : {0, 1}) {
    const TetMesh rest = extractLevel(mesh, level);
    RunRecorder recorder(dir / ("level" + std::to_string(level) + ".pvd"));
    for (int frame = 0; frame < 4; ++frame) {
      const Eigen::Matrix3d turn =
          Eigen::AngleAxisd(0.4 * frame, Eigen::Vector3d(0.2, 1, -0.3).normalized())
              .toRotationMatrix();
      const Points3 moved =
          (rest.nodes * turn.transpose()).rowwise() + Eigen::RowVector3d(0.3 * frame, -1, 2);
      recorder.addFrame(0.1 * frame, rest, test::unloadedFrame(rest, moved), level);
    }
  }
  LevelComparison comparison(mesh, skin(), {dir / "level1.pvd", dir / "level0.pvd"}, "block.json");
  ASSERT_FALSE(comparison.simulated());
  ASSERT_EQ(comparison.recordedFrames(), 4u);
  EXPECT_EQ(comparison.level(0), 1);
  EXPECT_EQ(comparison.level(1), 0);
  comparison.compare();
  for (int frame = 1; frame < 4; ++frame) {
    comparison.advance();
    comparison.compare();
  }
  EXPECT_THROW(comparison.advance(), Error);  // no frame left
  EXPECT_NEAR(comparison.frames().back().time, 0.3, 1e-12);
  // The surface turned and moved ...
  EXPECT_GT((comparison.surface(1).deformed->positions - skin().positions).norm(), 0.5);
  // ... alike on both levels.
  const ErrorSpread e = comparison.overall(1);
  EXPECT_LT(e.distance.max, 1e-12 * comparison.diagonal());
  EXPECT_LT(e.angle.max, 1e-6);
  EXPECT_EQ(comparison.meanStepSeconds(1), 0);  // (not simulated here)
}

// Level 0 is coarser than level 1: the wobble bends it otherwise, and the
// series holds a part per level with the errors and the carried stress;
// the table a row per frame and level.
TEST(LevelComparison, RecordsAPartPerLevelAndATable) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = twoLevels();
  LevelComparison comparison(mesh, skin(), {wobble(0), wobble(1)}, 1, "block.json");
  comparison.record(dir / "compare.pvd");
  comparison.compare();
  for (int i = 0; i < 8; ++i) comparison.advance();
  comparison.compare();
  comparison.writeFrameTable(dir / "compare.csv");

  const ErrorSpread coarse = comparison.overall(0);
  EXPECT_GT(coarse.distance.max, 0);
  EXPECT_GE(coarse.distance.max, coarse.distance.p99);
  EXPECT_GE(coarse.distance.p99, coarse.distance.median);
  EXPECT_EQ(comparison.overall(1).distance.max, 0);  // the reference
  // Both at rest: to rounding (each binding rebuilds the rest surface).
  EXPECT_LT(comparison.frames()[0].errors[0].distance.max, 1e-12 * comparison.diagonal());
  EXPECT_GT(comparison.frames()[1].stepSeconds[0], 0);

  const PvdSeries series = PvdSeries::read(dir / "compare.pvd");
  ASSERT_EQ(series.size(), 4u);  // 2 frames x 2 parts
  EXPECT_EQ(series.entries()[2].part, 0);
  EXPECT_EQ(series.entries()[3].part, 1);
  const vtkSmartPointer<vtkPolyData> last = readVtp(dir / series.entries()[2].file);
  for (const char* name : {arrays::kSurfaceError, arrays::kRelativeError, arrays::kNormalAngle,
                           arrays::kVonMisesStress, arrays::kEquivalentStrain}) {
    vtkDataArray* array = last->GetPointData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), skin().vertexCount()) << name;
  }
  double largest = 0;
  vtkDataArray* error = last->GetPointData()->GetArray(arrays::kSurfaceError);
  for (Index v = 0; v < error->GetNumberOfTuples(); ++v)
    largest = std::max(largest, error->GetTuple1(v));
  // (The spread over all frames keeps floats.)
  EXPECT_NEAR(largest, coarse.distance.max, 1e-6 * largest);

  const std::string table = test::readText(dir / "compare.csv");
  EXPECT_EQ(table.rfind("frame,time,run,level,step_ms,distance_max,", 0), 0u);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 5);  // header, 2 frames x 2 runs
  EXPECT_NE(table.find("\n1,0.08,0,0,"), std::string::npos) << table;
}

// A scene of two bunnies compared on levels 0 and 1, without gravity:
// the first held at its base and set swinging (its motion differs by
// level), the second sent off at 1 m/s, free (a rigid motion, which every
// level deforms its skin alike). Per body, the second's errors are
// rounding and the first's are not; the whole skin's are the first's; the
// table has a row per frame, level and body.
nlohmann::json swingAndGlide() {
  const std::string bunny = test::kSampleData + "bunny.json",
                    skin8k = test::kSampleData + "bunny_8k.obj";
  nlohmann::json swinging = {{"dataset", bunny},
                             {"surface", skin8k},
                             {"velocity", {3, 0, 0}},
                             {"held_box", {-10, -1, -10, 10, 1.5, 10}},
                             {"material", {{"mass_damping", 0}}}};
  nlohmann::json gliding = {{"dataset", bunny},
                            {"surface", skin8k},
                            {"translate", {40, 0, 0}},
                            {"velocity", {0, 0, 1}},
                            {"material", {{"mass_damping", 0}}}};
  return {{"format", "tetskin-scene"},
          {"version", 1},
          {"gravity", {0, 0, 0}},
          {"bodies", {swinging, gliding}}};
}

std::vector<SceneLevel> sceneLevels(const nlohmann::json& json, std::vector<int> levels) {
  const Scene scene = parseScene(json, "scene.json", ".");
  std::vector<SceneLevel> runs;
  for (const int level : levels) {
    Scene atLevel = scene;
    for (SceneBody& body : atLevel.bodies) body.level = level;
    SceneRun run = loadScene(atLevel);
    RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
    spec.options.solver = SolverKind::ConjugateGradient;  // (as wobble(): no timed choice)
    runs.push_back({level, std::move(run), std::move(spec)});
  }
  return runs;
}

TEST(LevelComparison, ComparesASceneBodyByBody) {
  const test::ScratchDir dir;
  LevelComparison comparison(sceneLevels(swingAndGlide(), {0, 1}), 1);
  ASSERT_EQ(comparison.bodyCount(), 2u);
  EXPECT_EQ(comparison.body(1).firstVertex, comparison.body(0).vertexCount);
  EXPECT_EQ(comparison.level(0), 0);
  EXPECT_GT(comparison.elementCount(1), comparison.elementCount(0));
  comparison.compare();
  for (int i = 0; i < 10; ++i) comparison.advance();
  comparison.compare();
  comparison.writeFrameTable(dir / "compare.csv");

  const ErrorSpread swinging = comparison.overall(0, 0), gliding = comparison.overall(0, 1);
  EXPECT_GT(swinging.distance.max, 1e-3 * comparison.bodyDiagonal(0));
  // (What is left of the glide is the solver's tolerance, 1e-6 of the residual.)
  EXPECT_LT(gliding.distance.max, 1e-5 * comparison.bodyDiagonal(1));
  EXPECT_EQ(comparison.overall(0).distance.max, swinging.distance.max);
  // The glide moved the second body's skin 1 m/s for 10 steps.
  const Points3& moved = comparison.surface(0).deformed->positions;
  const BodyRange& second = comparison.body(1);
  EXPECT_NEAR(
      moved(second.firstVertex, 2) - comparison.surface(0).surface.positions(second.firstVertex, 2),
      10 * comparison.session(0)->options().timeStep, 1e-6);

  const std::string table = test::readText(dir / "compare.csv");
  EXPECT_NE(table.find("angle_median,body\n"), std::string::npos) << table;
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 9);  // header, 2 frames x 2 runs x 2
  EXPECT_NE(table.find(",1\n1,"), std::string::npos) << table;

  // A body without a surface takes its level's boundary: skins that differ by level.
  nlohmann::json bare = swingAndGlide();
  bare["bodies"][1].erase("surface");
  EXPECT_NE(test::errorText([&] {
              LevelComparison(sceneLevels(bare, {0, 1}), 1);
            }).find("its skins differ from those on level 1: give every body a surface"),
            std::string::npos);
}

TEST(LevelComparison, RefusesTooFewRunsAndRunsThatDoNotMatch) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = twoLevels();
  EXPECT_EQ(test::errorText([&] { LevelComparison(mesh, skin(), {wobble(0)}, 0, "b"); }),
            "a comparison needs at least two levels, 1 given");
  EXPECT_EQ(test::errorText([&] {
              LevelComparison(mesh, skin(), {wobble(0), wobble(1)}, 2, "b");
            }),
            "the reference is run 2 of 2");
  const TetMesh rest = extractLevel(mesh, 0);
  {
    RunRecorder three(dir / "three.pvd"), two(dir / "two.pvd"), late(dir / "late.pvd");
    for (int frame = 0; frame < 3; ++frame) {
      three.addFrame(0.1 * frame, rest, test::unloadedFrame(rest, rest.nodes), 0);
      late.addFrame(0.1 * frame + (frame == 2 ? 0.05 : 0), rest,
                    test::unloadedFrame(rest, rest.nodes), 0);
      if (frame < 2) two.addFrame(0.1 * frame, rest, test::unloadedFrame(rest, rest.nodes), 0);
    }
  }
  const std::string two = (dir / "two.pvd").string(), late = (dir / "late.pvd").string();
  EXPECT_EQ(test::errorText([&] {
              LevelComparison(mesh, skin(), {dir / "three.pvd", dir / "two.pvd"}, "b");
            }),
            two + ": has 2 frames, " + (dir / "three.pvd").string() +
                " 3: compared runs are matched frame by frame");
  EXPECT_EQ(test::errorText([&] {
              LevelComparison(mesh, skin(), {dir / "three.pvd", dir / "late.pvd"}, "b");
            }),
            late + ": frame 2 is at time 0.25, in " + (dir / "three.pvd").string() +
                " at 0.2: compared runs are matched frame by frame");
}

}  // namespace
}  // namespace tetskin
