// SPDX-License-Identifier: AGPL-3.0-or-later
// The run request (RunRequest.h): its defaults, the dataset config applied
// under the values given, the held box, errors named as each front end's
// user names options, and the session's one channel of warnings.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "BlockRun.h"
#include "ExpectError.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/core/Appearance.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfacePieces.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::test {
namespace {

DatasetConfig zUpStiffConfig() {
  DatasetConfig config;
  config.up = UpAxis::Z;
  config.elasticity.youngsModulus = 3e5;
  config.elasticity.density = 500;
  return config;
}

// One name per option: a flag is its key in kebab case (after the fur
// section's prefix), so a config's key, Python's keyword and the command
// line's flag are one name; an old flag differs from the new one.
TEST(RunRequest, EveryOptionsFlagIsItsKey) {
  std::vector<std::pair<const NumberOption*, std::string>> options;
  for (const MaterialField& f : materialFields()) options.emplace_back(f.option, "--");
  for (const ScenarioField& f : scenarioFields()) options.emplace_back(f.option, "--");
  for (const NumberOption* o :
       {&simulation_option::kTimeStep, &simulation_option::kTolerance,
        &simulation_option::kGuessSolutions, &simulation_option::kCoarseReuse,
        &simulation_option::kMaxIterations, &simulation_option::kFriction,
        &simulation_option::kFloorStiffness})
    options.emplace_back(o, "--");
  for (const NumberOption* o :
       {&fur_option::kShells, &fur_option::kMinShells, &fur_option::kLength, &fur_option::kDensity,
        &fur_option::kTextureSize, &fur_option::kTextureRepeats, &fur_option::kDrag,
        &fur_option::kVelvet, &fur_option::kSeed})
    options.emplace_back(o, "--fur-");
  for (const NumberOption* o :
       {&recording_option::kSteps, &recording_option::kEvery, &kPiecesOption, &kLevelOption})
    options.emplace_back(o, "--");
  const auto expectFlagIsKey = [](const char* key, const char* flag, const std::string& prefix) {
    std::string kebab = key;
    std::replace(kebab.begin(), kebab.end(), '_', '-');
    EXPECT_EQ(flag, prefix + kebab) << key;
  };
  for (const auto& [option, prefix] : options) {
    expectFlagIsKey(option->key, option->flag, prefix);
    EXPECT_NE(std::string(option->oldFlag), option->flag) << option->key;
  }
  // The enum options: (key, flag, prefix).
  const std::vector<std::tuple<const char*, const char*, std::string>> enums = {
      {simulation_option::kSolver.key, simulation_option::kSolver.flag, "--"},
      {simulation_option::kTangent.key, simulation_option::kTangent.flag, "--"},
      {simulation_option::kCoarseOperators.key, simulation_option::kCoarseOperators.flag, "--"},
      {simulation_option::kCoarseLevels.key, simulation_option::kCoarseLevels.flag, "--"},
      {kUpOption.key, kUpOption.flag, "--"},
      {binding_option::kMethod.key, binding_option::kMethod.flag, "--"},
      {binding_option::kOffset.key, binding_option::kOffset.flag, "--"},
      {kCompressOption.key, kCompressOption.flag, "--"},
      {fur_option::kLighting.key, fur_option::kLighting.flag, "--fur-"},
      // (and the switches and the scenario's name)
      {fur_option::kFins.key, fur_option::kFins.flag, "--fur-"},
      {fur_option::kAdaptiveShells.key, fur_option::kAdaptiveShells.flag, "--fur-"},
      {kScenarioOption.key, kScenarioOption.flag, "--"}};
  for (const auto& [key, flag, prefix] : enums) expectFlagIsKey(key, flag, prefix);
  EXPECT_STREQ(fur_option::kAdaptiveShells.oldFlag, "--fur-adaptive");
}

TEST(RunRequest, EnumOptionsNameThemselvesAsEachFrontEndDoes) {
  const EnumOption<SolverKind>& solver = simulation_option::kSolver;
  EXPECT_EQ(nameOf(solver, OptionNames::Flags), "--solver");
  EXPECT_EQ(nameOf(solver, OptionNames::Keys), "solver");
  EXPECT_EQ(nameOf(solver, OptionNames::Words), "the solver");
  // --help's text: the help before the names, then the names with theirs.
  EXPECT_EQ(simulation_option::kCoarseOperators.fullHelp(),
            "multigrid: " + helpOf<CoarseOperators>());
  EXPECT_EQ(solver.fullHelp(), helpOf<SolverKind>());
}

TEST(RunRequest, DefaultsAreOneSetForEveryFrontEnd) {
  const RunSpec spec = resolveRun(RunRequest{}, uprightBlock(), DatasetConfig{});
  EXPECT_EQ(spec.scenario, "wobble");
  EXPECT_EQ(spec.options.solver, SolverKind::Automatic);
  // The library's own default stays cg: the request's is a choice of its own.
  EXPECT_EQ(SimulationOptions{}.solver, SolverKind::ConjugateGradient);
  EXPECT_EQ(spec.options.timeStep, simulation_option::kTimeStep.defaultValue);
  EXPECT_EQ(spec.options.tolerance, simulation_option::kTolerance.defaultValue);
  EXPECT_EQ(spec.options.gravity, Eigen::Vector3d(0, -kStandardGravity, 0));
  EXPECT_FALSE(spec.options.floorHeight);
}

TEST(RunRequest, TheConfigAppliesUnderTheValuesGiven) {
  RunRequest request;
  request.material.set(material_option::kPoissonRatio, 0.45);
  const RunSpec spec = resolveRun(request, uprightBlock(), zUpStiffConfig());
  EXPECT_EQ(spec.options.material.youngsModulus, 3e5);  // the config's
  EXPECT_EQ(spec.options.material.density, 500);
  EXPECT_EQ(spec.options.material.poissonRatio, 0.45);  // given
  EXPECT_EQ(spec.options.up, UpAxis::Z);                // the config's up, gravity down it
  EXPECT_EQ(spec.options.gravity, Eigen::Vector3d(0, 0, -kStandardGravity));
  request.up = UpAxis::X;
  request.gravity = Eigen::Vector3d(1, 2, 3);
  const RunSpec given = resolveRun(request, uprightBlock(), zUpStiffConfig());
  EXPECT_EQ(given.options.up, UpAxis::X);
  EXPECT_EQ(given.options.gravity, Eigen::Vector3d(1, 2, 3));
}

TEST(RunRequest, ErrorsNameTheOptionAsTheFrontEndsUserDoes) {
  RunRequest request;
  request.material.set(material_option::kPoissonRatio, 0.5);
  request.names = OptionNames::Flags;
  EXPECT_NE(errorText([&] { resolveRun(request, uprightBlock(), {}); }).find("--poisson-ratio: "),
            std::string::npos);
  request.names = OptionNames::Keys;
  EXPECT_NE(errorText([&] { resolveRun(request, uprightBlock(), {}); }).find("poisson_ratio: "),
            std::string::npos);
  RunRequest box;
  box.fixedBox = BoundingBox{};
  box.fixedBox->min = {5, 5, 5};
  box.fixedBox->max = {6, 6, 6};
  box.names = OptionNames::Words;
  EXPECT_EQ(errorText([&] { resolveRun(box, uprightBlock(), {}); }).rfind("the fixed box: ", 0),
            0u);
  box.names = OptionNames::Flags;
  EXPECT_EQ(errorText([&] { resolveRun(box, uprightBlock(), {}); }).rfind("--fixed-box: ", 0), 0u);
  RunRequest unknown;
  unknown.scenario = "spin";
  EXPECT_EQ(errorText([&] { resolveRun(unknown, uprightBlock(), {}); }),
            "unknown scenario 'spin' (known: " + listed(scenarioNames()) + ")");
}

TEST(RunRequest, AHeldBoxAddsTheNodesInside) {
  RunRequest request;
  request.scenario = "sag";
  request.parameters.baseShare = 0;
  request.parameters.fixedNodes = {0};
  request.fixedBox = BoundingBox{};
  request.fixedBox->min = {-1, 0.35, -1};  // the block's top layer (y = 0.4)
  request.fixedBox->max = {1, 1, 1};
  const MultiLevelTetMesh mesh = uprightBlock();
  const RunSpec spec = resolveRun(request, mesh, {});
  std::vector<int> expected = {0};
  for (Index i = 0; i < mesh.nodes.rows(); ++i)
    if (mesh.nodes(i, 1) >= 0.35) expected.push_back(static_cast<int>(i));
  EXPECT_EQ(spec.parameters.fixedNodes, expected);
}

// The block's top (y = 0.4, 0.2 x 0.2: 2 x 2 cells, 8 faces) by a box and
// by a face set; errors name the request, the file and line, or the row.
TEST(RunRequest, SurfaceLoadsSelectBoundaryFacesByABoxOrAFaceSet) {
  const MultiLevelTetMesh mesh = uprightBlock();
  RunRequest request;
  SurfaceLoadRequest top;
  top.name = "--load-box";
  top.pressure = 100;
  top.box = BoundingBox{{-1, 0.39, -1}, {1, 1, 1}};
  request.surfaceLoads = {top};
  const RunSpec spec = resolveRun(request, mesh, {});
  ASSERT_EQ(spec.parameters.surfaceLoads.size(), 1u);
  const SurfaceLoad& load = spec.parameters.surfaceLoads[0];
  ASSERT_EQ(load.faces.rows(), 8);
  const Eigen::VectorXd rest = mesh.nodes.reshaped<Eigen::RowMajor>();
  EXPECT_NEAR(loadedArea(load, rest), 0.04, 1e-15);
  // Wound outward: the pressure pushes down, into the block.
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(rest.size());
  addSurfaceLoadForces(load, rest, rest, 1.0, forces);
  EXPECT_NEAR(forces.reshaped(3, rest.size() / 3).rowwise().sum().y(), -4, 1e-13);

  // The same faces from a file, each corner order any, gives the same load.
  ScratchDir dir;
  std::string lines = "# the top\n";
  for (Index f = 0; f < load.faces.rows(); ++f)
    lines += std::to_string(load.faces(f, 2)) + " " + std::to_string(load.faces(f, 0)) + " " +
             std::to_string(load.faces(f, 1)) + "\n";
  SurfaceLoadRequest byFile = top;
  byFile.box.reset();
  byFile.faceFile = dir.write("top.faces", lines);
  request.surfaceLoads = {byFile};
  EXPECT_EQ(resolveRun(request, mesh, {}).parameters.surfaceLoads[0].faces, load.faces);

  // An inner face, a face named twice, a line that is no face.
  const TetMesh level = extractLevel(mesh, 0);
  const auto refusal = [&](const std::string& content) {
    SurfaceLoadRequest bad = byFile;
    bad.faceFile = dir.write("bad.faces", content);
    return errorText([&] { selectSurfaceLoad(bad, level); });
  };
  const std::string file = (dir / "bad.faces").string();
  const std::array<int, 3> inner = innerFace(level);
  EXPECT_EQ(refusal(std::to_string(load.faces(0, 0)) + " " + std::to_string(load.faces(0, 1)) +
                    " " + std::to_string(load.faces(0, 2)) + "\n" + std::to_string(inner[0]) + " " +
                    std::to_string(inner[1]) + " " + std::to_string(inner[2]) + "\n"),
            file + ":2: nodes " + std::to_string(inner[0]) + ", " + std::to_string(inner[1]) +
                ", " + std::to_string(inner[2]) + " are not a face of the boundary");
  const std::string first = std::to_string(load.faces(0, 0)) + " " +
                            std::to_string(load.faces(0, 1)) + " " +
                            std::to_string(load.faces(0, 2)) + "\n";
  EXPECT_EQ(refusal(first + "# again\n" + first), file + ":3: names the face of line 1 again");
  EXPECT_EQ(refusal("1 2\n"), file + ":1: face (three node numbers): expected 3 values, found 2");
  // A box around no boundary face, and no selection.
  SurfaceLoadRequest nowhere = top;
  nowhere.box = BoundingBox{{5, 5, 5}, {6, 6, 6}};
  EXPECT_EQ(errorText([&] { selectSurfaceLoad(nowhere, level); }),
            "--load-box: no face of the boundary lies in 5,5,5 .. 6,6,6 (the body spans 0,0,0 .. "
            "0.2,0.4,0.2)");
  nowhere.box.reset();
  EXPECT_EQ(errorText([&] { selectSurfaceLoad(nowhere, level); }),
            "--load-box: no faces are selected (give a box or a face set)");
  // Rows of node ids, as Python gives them.
  SurfaceLoadRequest rows = top;
  rows.box.reset();
  rows.name = "load_faces";
  rows.faceNodes = load.faces;
  EXPECT_EQ(selectSurfaceLoad(rows, level).faces, load.faces);
  rows.faceNodes.row(1) << 0, 1, 999;
  EXPECT_EQ(errorText([&] { selectSurfaceLoad(rows, level); }),
            "load_faces: row 1: node 999 does not exist (the body has " +
                std::to_string(level.nodeCount()) + " nodes)");
}

TEST(RunRequest, WarningsComeOnceThroughTheSession) {
  RunRequest request;
  request.floorHeight = 0.1;  // through the block (0 .. 0.4 up)
  request.settings.timeStep = 0.01;
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationSession session(mesh, resolveRun(request, mesh, {}));
  const std::vector<std::string> first = session.takeWarnings(OptionNames::Flags);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_NE(first[0].find("start below the floor"), std::string::npos);
  EXPECT_TRUE(session.takeWarnings(OptionNames::Flags).empty());  // once
  // A solve held to one iteration stops short of the tolerance: said when
  // the count of such steps grows, naming the solver as the user would.
  RunRequest limited;
  limited.settings.maxIterations = 1;
  limited.settings.solver = SolverKind::ConjugateGradient;
  limited.settings.timeStep = 0.01;
  SimulationSession capped(mesh, resolveRun(limited, mesh, {}));
  EXPECT_TRUE(capped.takeWarnings(OptionNames::Keys).empty());
  capped.run(2, 1);
  const std::vector<std::string> shortfall = capped.takeWarnings(OptionNames::Keys);
  ASSERT_EQ(shortfall.size(), 1u);
  EXPECT_NE(shortfall[0].find("2 steps stopped at the iteration limit (1)"), std::string::npos);
  EXPECT_NE(shortfall[0].find("solver='multigrid'"), std::string::npos);
  EXPECT_TRUE(capped.takeWarnings(OptionNames::Keys).empty());
}

}  // namespace
}  // namespace tetskin::test
