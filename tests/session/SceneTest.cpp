// SPDX-License-Identifier: AGPL-3.0-or-later
// Scenes (SceneFile.h, SceneRun.h): the bundled scene read with its paths
// relative to it; bad scenes refused naming the file and the field; and
// bodies dropped into a bowl and onto a sphere come to rest on their skin,
// its deepest vertex less than 0.5% of the body's diagonal inside (measured
// against the exact sphere, not the contact's own distances), the contact
// forces equal to the weight within 1%.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "ExpectError.h"
#include "SampleData.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/session/RunProbe.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::test {
namespace {

const std::filesystem::path kBowlScene = kSampleData + "scenes/bunny-in-bowl.json";

nlohmann::json sceneJson() {
  return nlohmann::json::parse(readText(kBowlScene));
}

Scene parse(const nlohmann::json& json) {
  return parseScene(json, "scene.json", kSampleData + "scenes");
}

TEST(SceneFile, TheBundledSceneIsReadWithPathsRelativeToIt) {
  const Scene scene = readScene(kBowlScene);
  ASSERT_EQ(scene.bodies.size(), 1u);
  const SceneBody& body = scene.bodies[0];
  EXPECT_TRUE(std::filesystem::equivalent(body.dataset, kSampleData + "bunny.json"));
  ASSERT_TRUE(body.surface);
  EXPECT_TRUE(std::filesystem::equivalent(*body.surface, kSampleData + "bunny_8k.obj"));
  EXPECT_EQ(body.level, 1);
  EXPECT_EQ(body.scenario, "free");
  ASSERT_EQ(scene.obstacles.size(), 1u);
  EXPECT_TRUE(
      std::filesystem::equivalent(scene.obstacles[0].surface, kSampleData + "scenes/bowl.obj"));
  EXPECT_EQ(scene.obstacles[0].staticFriction, 0.4);
  EXPECT_EQ(scene.obstacles[0].kineticFriction, 0.4);
  EXPECT_EQ(scene.steps, 240);
}

TEST(SceneFile, BadScenesNameTheFileAndTheField) {
  const auto expect = [](const auto& edit, const std::string& what) {
    nlohmann::json json = sceneJson();
    edit(json);
    expectErrorAt([&] { parse(json); }, "scene.json", 0, what);
  };
  expect([](auto& j) { j["format"] = "tetskin-dataset"; }, "/format: must be \"tetskin-scene\"");
  expect([](auto& j) { j["bodies"][0]["colour"] = 1; }, "/bodies/0/colour: is not a known field");
  expect([](auto& j) { j["obstacles"][0]["scale"] = "big"; },
         "/obstacles/0/scale: must be a number");
  expect([](auto& j) { j["obstacles"][0]["scale"] = -1; }, "/obstacles/0/scale: must lie in");
  expect(
      [](auto& j) {
        j["bodies"][0]["translate"] = {1, 2};
      },
      "/bodies/0/translate: must be an array of 3 finite numbers");
  expect([](auto& j) { j["bodies"][0]["material"]["youngs_modulus"] = -5; },
         "/bodies/0/material/youngs_modulus:");
  expect([](auto& j) { j["bodies"][0]["material"]["stiffness"] = 5; },
         "/bodies/0/material/stiffness: is not a known field");
  expect([](auto& j) { j["bodies"][0][simulation_option::kContactPoints.key] = "hands"; },
         "/bodies/0/contact_points: must be one of skin, cage");
  expect([](auto& j) { j["bodies"][0]["scenario"] = "fly"; }, "/bodies/0/scenario: must be one of");
  expect(
      [](auto& j) {
        j["obstacles"][0]["static_friction"] = 0.2;
        j["obstacles"][0]["kinetic_friction"] = 0.3;
        j["obstacles"][0].erase("friction");
      },
      "/obstacles/0/kinetic_friction: must not exceed static_friction");
  expect(
      [](auto& j) {
        j["obstacles"][0]["motion"] = {{{"time", 1}}, {{"time", 0.5}}};
      },
      "/obstacles/0/motion/1/time: must be later");
  expect([](auto& j) { j.erase("bodies"); }, "/bodies: is missing");
  expect([](auto& j) { j["bodies"][0]["self_contact"] = "yes"; },
         "/bodies/0/self_contact: must be");
  expect([](auto& j) { j["skin_contact"]["thickness"] = -0.1; }, "/skin_contact/thickness:");
  expect(
      [](auto& j) {
        j["skin_contact"] = {{"static_friction", 0.2}, {"kinetic_friction", 0.3}};
      },
      "/skin_contact/kinetic_friction: must not exceed static_friction");
  expect([](auto& j) { j["skin_contact"]["range"] = 1; },
         "/skin_contact/range: is not a known field");
}

// A body's self_contact and the scene's skin_contact reach the run's
// SkinCollisions; without them, the defaults (no self-contact).
TEST(SceneFile, SelfContactAndTheSkinsContactReachTheRun) {
  nlohmann::json json = sceneJson();
  const Scene plain = parse(json);
  EXPECT_FALSE(plain.bodies[0].selfContact);
  EXPECT_FALSE(plain.skinContact);
  json["bodies"][0]["self_contact"] = true;
  json["skin_contact"] = {{"thickness", 0.05}, {"stiffness", 2e4}, {"friction", 0.2}};
  const Scene scene = parse(json);
  ASSERT_TRUE(scene.bodies[0].selfContact);
  EXPECT_TRUE(*scene.bodies[0].selfContact);
  ASSERT_TRUE(scene.skinContact);
  EXPECT_EQ(scene.skinContact->thickness, 0.05);
  EXPECT_EQ(scene.skinContact->stiffness, 2e4);
  EXPECT_EQ(scene.skinContact->staticFriction, 0.2);
  EXPECT_EQ(scene.skinContact->kineticFriction, 0.2);
  const SceneRun run = loadScene(scene);
  const SkinCollisions& skins = run.request.settings.skinCollisions;
  EXPECT_TRUE(skins.self);
  EXPECT_EQ(skins.thickness, 0.05);
  EXPECT_EQ(skins.stiffness, 2e4);
  EXPECT_EQ(skins.kineticFriction, 0.2);
  EXPECT_FALSE(loadScene(plain).request.settings.skinCollisions.self);
}

TEST(SceneRun, MissingAndOpenFilesAreNamedByTheirField) {
  ScratchDir dir;
  nlohmann::json json = sceneJson();
  json["obstacles"][0]["surface"] = (dir / "nowhere.obj").string();
  expectErrorAt([&] { loadScene(parse(json)); }, "scene.json", 0,
                "/obstacles/0/surface: " + (dir / "nowhere.obj").string() + ": no such file");
  // A box without its top: not closed.
  SurfaceMesh open = box({0, 0, 0}, {1, 1, 1});
  open.triangles.conservativeResize(open.triangles.rows() - 2, 3);
  writeObj((dir / "open.obj").string(), open);
  json["obstacles"][0]["surface"] = (dir / "open.obj").string();
  expectErrorAt([&] { loadScene(parse(json)); }, "scene.json", 0, "/obstacles/0/surface: ");
  json = sceneJson();
  json["bodies"][0]["dataset"] = "missing.json";
  expectErrorAt([&] { loadScene(parse(json)); }, "scene.json", 0, "/bodies/0/dataset: ");
}

// The deepest a skin vertex lies inside the bowl's solid (inner radius 9,
// outer 9.6 about the origin, below the rim), from the exact spheres.
double deepestInBowl(const Points3& skin) {
  double deepest = -1e300;
  for (Index v = 0; v < skin.rows(); ++v) {
    const double r = skin.row(v).norm();
    if (r < 9.3 && -skin(v, 1) > r * std::cos(75 * M_PI / 180)) deepest = std::max(deepest, r - 9);
  }
  return deepest;
}

TEST(SceneRun, TheBunnyDroppedIntoTheBowlComesToRestOnItsSkin) {
  Scene scene = readScene(kBowlScene);
  scene.bodies[0].level = 0;
  // (Damped more than the config's, to settle in a few seconds.)
  scene.bodies[0].material.set(material_option::kMassDamping, 2.0);
  SceneRun run = loadScene(scene);
  ASSERT_TRUE(run.surface);
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  SimulationSession session(run.dataset.mesh, spec);
  session.bindSurface(run.surface->surface, run.surface->binding, "bunny.json");
  const double diagonal = boundingBox(run.surface->surface.positions).diagonal();
  for (int i = 0; i < 500; ++i) session.step();
  const SimulationState state = session.state();
  const Points3 skin = session.deformedSurface(state.positions).deformed->positions;
  EXPECT_LT(deepestInBowl(skin), 0.005 * diagonal);
  const double weight = session.simulation().nodeMasses().sum() * kStandardGravity;
  const Eigen::Vector3d support =
      session.simulation().contactForces(state).colwise().sum().transpose();
  EXPECT_NEAR(support.y(), weight, 0.01 * weight);
  EXPECT_LT(std::hypot(support.x(), support.z()), 0.01 * weight);
}

// A recorded scene: the control frames carry ContactForce (the run's
// contact forces, summed as Simulation::contactForces sums them), the skin
// frames Penetration, which matches the depth in the exact bowl within its
// tessellation's sag, and ContactForce, zero where the skin is outside.
TEST(SceneRun, TheRecordedRunCarriesTheContact) {
  ScratchDir dir;
  Scene scene = readScene(kBowlScene);
  scene.bodies[0].level = 0;
  SceneRun run = loadScene(scene);
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  SimulationSession session(run.dataset.mesh, spec);
  session.bindSurface(run.surface->surface, run.surface->binding, "bunny.json");
  session.record(dir / "run.pvd");
  session.recordFrame();  // frame 0: the start
  session.run(120, 120);  // frame 1: after 2 s
  const auto control = readVtu(dir / "run_frames/control_00001.vtu");
  const auto skin = readVtp(dir / "run_frames/surface_00001.vtp");
  vtkDataArray* nodeForces = control->GetPointData()->GetArray(arrays::kContactForce);
  vtkDataArray* penetration = skin->GetPointData()->GetArray(arrays::kPenetration);
  vtkDataArray* skinForces = skin->GetPointData()->GetArray(arrays::kContactForce);
  ASSERT_TRUE(nodeForces && penetration && skinForces);
  const Eigen::Vector3d expected =
      session.simulation().contactForces(session.state()).colwise().sum().transpose();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (vtkIdType i = 0; i < nodeForces->GetNumberOfTuples(); ++i)
    sum += Eigen::Map<const Eigen::Vector3d>(nodeForces->GetTuple3(i));
  EXPECT_LT((sum - expected).norm(), 1e-6 * expected.norm());
  EXPECT_GT(expected.norm(), 0);  // it has landed
  int inside = 0;
  for (vtkIdType v = 0; v < skin->GetNumberOfPoints(); ++v) {
    const Eigen::Vector3d p(skin->GetPoint(v));
    const double depth = penetration->GetTuple1(v);
    const double force = Eigen::Vector3d(skinForces->GetTuple3(v)).norm();
    if (depth > 0) ++inside;
    EXPECT_EQ(force > 0, depth > 0) << "vertex " << v;
    // Near the bowl's inner wall (away from the rim): the exact depth.
    if (depth > -0.5 && -p.y() > 0.5 * p.norm()) {
      EXPECT_NEAR(depth, p.norm() - 9, 0.01) << v;
    }
  }
  EXPECT_GT(inside, 0);
}

// The obstacles as each frame poses them: a static one written once and
// named by every frame, a moving one written per frame where its keyframes
// put it at that frame's time.
TEST(SceneRun, TheRecordedRunPosesTheObstaclesAtEachFrame) {
  ScratchDir dir;
  nlohmann::json json = sceneJson();
  json["bodies"][0]["level"] = 0;
  nlohmann::json moving = json["obstacles"][0];
  moving["scale"] = 0.5;
  moving["translate"] = {0, 20, 0};
  moving["motion"] = {{{"time", 0}, {"translate", {0, 20, 0}}},
                      {{"time", 1}, {"translate", {4, 20, 0}}, {"rotate", {0, 90, 0}}}};
  json["obstacles"].push_back(moving);
  const SceneRun run = loadScene(parse(json));
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  SimulationSession session(run.dataset.mesh, spec);
  session.record(dir / "run.pvd");
  session.recordFrame();  // t = 0
  session.run(30, 30);    // t = 0.5 s
  const PvdSeries series = PvdSeries::read(dir / "run.pvd");
  std::vector<std::string> bowlFiles, movingFiles;
  for (const PvdSeries::Entry& e : series.entries()) {
    if (e.part == RunRecorder::kFirstObstaclePart) bowlFiles.push_back(e.file);
    if (e.part == RunRecorder::kFirstObstaclePart + 1) movingFiles.push_back(e.file);
  }
  EXPECT_EQ(bowlFiles, std::vector<std::string>(2, "run_frames/obstacle_0.vtp"));
  EXPECT_EQ(movingFiles, (std::vector<std::string>{"run_frames/obstacle_00000_1.vtp",
                                                   "run_frames/obstacle_00001_1.vtp"}));
  const SurfaceMesh bowl = readObj(kSampleData + "scenes/bowl.obj");
  const auto staticBowl = readVtp(dir / "run_frames/obstacle_0.vtp");
  const auto movedBowl = readVtp(dir / "run_frames/obstacle_00001_1.vtp");
  ASSERT_EQ(staticBowl->GetNumberOfPoints(), bowl.vertexCount());
  ASSERT_EQ(movedBowl->GetNumberOfPoints(), bowl.vertexCount());
  // About halfway through its motion at the frame's time (30 steps of the
  // scene's 1/60 s, rounded): 4 t along x, turned 90 t degrees about y.
  const double t = session.state().time;
  ASSERT_NEAR(t, 0.5, 1e-4);
  const Eigen::AngleAxisd turn(M_PI / 2 * t, Eigen::Vector3d::UnitY());
  double staticError = 0, movedError = 0;
  for (Index v = 0; v < bowl.vertexCount(); ++v) {
    const Eigen::Vector3d p = bowl.positions.row(v).transpose();
    staticError = std::max(staticError, (Eigen::Vector3d(staticBowl->GetPoint(v)) - p).norm());
    const Eigen::Vector3d moved = Eigen::Vector3d(4 * t, 20, 0) + 0.5 * (turn * p);
    movedError = std::max(movedError, (Eigen::Vector3d(movedBowl->GetPoint(v)) - moved).norm());
  }
  EXPECT_LT(staticError, 1e-9);
  EXPECT_LT(movedError, 1e-9);
}

// The bundled scene's bunny twice at level 0 (the second placed 30 m
// aside, stiffer, heavier, moving and held by a box around its lowest part;
// the first without a surface: its level's boundary is its skin).
nlohmann::json twoBunnies() {
  nlohmann::json json = sceneJson();
  nlohmann::json& first = json["bodies"][0];
  first["level"] = 0;
  first.erase("surface");
  nlohmann::json second = first;
  second["surface"] = "../bunny_8k.obj";
  second["translate"] = {30, 0, 0};
  second["material"] = {{"youngs_modulus", 5e5}, {"density", 200}};
  second["velocity"] = {1, 0, 0};
  second["self_contact"] = true;
  second["held_box"] = {20, -100, -100, 40, 1, 100};
  json["bodies"].push_back(second);
  return json;
}

// Two bodies become one run: one level of both levels' nodes, one skin of
// both skins, each body's material over its elements, its velocity on its
// nodes, its held box's nodes held (numbered in the union), and its
// recorded parts of its own.
TEST(SceneRun, SeveralBodiesBecomeOneRunWithTheirOwnMaterialsStartsAndParts) {
  ScratchDir dir;
  const Scene scene = parse(twoBunnies());
  const SceneRun run = loadScene(scene);
  const Dataset bunny = loadDataset(kSampleData + "bunny.json");
  const LevelRange& level0 = bunny.mesh.levels[0];
  ASSERT_EQ(run.dataset.mesh.levels.size(), 1u);
  EXPECT_EQ(run.dataset.mesh.nodes.rows(), 2 * level0.nodeCount);
  const std::vector<RunBody>& bodies = run.request.bodies;
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(bodies[1].name, "/bodies/1");
  EXPECT_EQ(bodies[1].range.firstNode, level0.nodeCount);
  EXPECT_EQ(bodies[1].range.firstElement, level0.elementCount);
  const SurfaceMesh bunny8k = readObj(kSampleData + "bunny_8k.obj");
  EXPECT_EQ(bodies[1].range.vertexCount, bunny8k.vertexCount());
  ASSERT_TRUE(run.surface);
  EXPECT_EQ(run.surface->surface.vertexCount(),
            bodies[1].range.firstVertex + bunny8k.vertexCount());
  // The second body placed as the first, 30 m aside and 6 m up (the
  // first's translate is [0, -6, 0], the second's [30, 0, 0]).
  const Points3 shift = run.dataset.mesh.nodes.bottomRows(level0.nodeCount) -
                        run.dataset.mesh.nodes.topRows(level0.nodeCount);
  EXPECT_LT((shift.rowwise() - Eigen::RowVector3d(30, 6, 0)).cwiseAbs().maxCoeff(), 1e-9);
  const std::vector<int>& held = run.request.parameters.fixedNodes;
  ASSERT_FALSE(held.empty());
  for (const int node : held) {
    EXPECT_GE(node, level0.nodeCount);
    EXPECT_LE(run.dataset.mesh.nodes(node, 1), 1);
  }

  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  ASSERT_EQ(spec.options.materialRegions.size(), 2u);
  EXPECT_EQ(spec.options.materialRegions[1].material.youngsModulus, 5e5);
  EXPECT_EQ(spec.options.materialRegions[1].material.density, 200);
  EXPECT_EQ(spec.options.materialRegions[0].material.youngsModulus,
            bunny.config.elasticity.youngsModulus);
  EXPECT_EQ(spec.options.skinCollisions.selfBodies, std::vector<int>{1});
  SimulationSession session(run.dataset.mesh, spec);
  session.bindSurface(run.surface->surface, run.surface->binding, "scene.json");
  const SimulationState start = session.state();
  EXPECT_EQ(start.velocities.topRows(level0.nodeCount).cwiseAbs().maxCoeff(), 0);
  for (Index v = level0.nodeCount; v < 2 * level0.nodeCount; ++v)
    if (!std::binary_search(held.begin(), held.end(), static_cast<int>(v))) {
      EXPECT_EQ(start.velocities.row(v), Eigen::RowVector3d(1, 0, 0)) << v;
    }
  // Each body's mass is its own density's.
  const Eigen::VectorXd mass = session.simulation().nodeMasses();
  EXPECT_NEAR(mass.tail(level0.nodeCount).sum(), 2 * mass.head(level0.nodeCount).sum(),
              1e-9 * mass.sum());

  session.record(dir / "run.pvd");
  session.recordFrame();
  session.run(2, 1);
  const PvdSeries series = PvdSeries::read(dir / "run.pvd");
  std::map<int, int> filesOfPart;
  for (const PvdSeries::Entry& e : series.entries()) ++filesOfPart[e.part];
  EXPECT_EQ(filesOfPart, (std::map<int, int>{{0, 3}, {1, 3}, {2, 3}, {3, 3}, {4, 3}}));
  EXPECT_EQ(RunRecorder::firstObstaclePart(2), 4);
  const auto control = readVtu(dir / "run_frames/control_00002_1.vtu");
  const auto skin = readVtp(dir / "run_frames/surface_00002_1.vtp");
  EXPECT_EQ(control->GetNumberOfPoints(), level0.nodeCount);
  EXPECT_EQ(control->GetNumberOfCells(), level0.elementCount);
  EXPECT_EQ(skin->GetNumberOfPoints(), bunny8k.vertexCount());
  // The frame's points are the body's nodes where the run has them.
  const SimulationState end = session.state();
  double largest = 0;
  for (Index v = 0; v < level0.nodeCount; ++v)
    largest = std::max(largest, (Eigen::Vector3d(control->GetPoint(v)) -
                                 end.positions.row(level0.nodeCount + v).transpose())
                                    .norm());
  EXPECT_LT(largest, 1e-6);
  // Replayed as the union the scene stepped: the bodies' frames side by
  // side, the rest mesh the scene's, the held nodes in the union's numbers.
  const RecordedRun recorded(dir / "run.pvd");
  ASSERT_EQ(recorded.bodyCount(), 2);
  EXPECT_EQ(recorded.frameCount(), 3u);
  EXPECT_EQ(recorded.bodies()[1].firstNode, level0.nodeCount);
  EXPECT_EQ(recorded.bodies()[1].firstElement, level0.elementCount);
  EXPECT_EQ(recorded.level(), 0);
  EXPECT_FALSE(recorded.surfaceFile());
  EXPECT_EQ(recorded.prescribedNodes(), held);
  const TetMesh rest = recorded.rest();
  const TetMesh united = extractLevel(run.dataset.mesh, 0);
  EXPECT_EQ(rest.elements, united.elements);
  EXPECT_LT((rest.nodes - united.nodes).cwiseAbs().maxCoeff(), 1e-9);
  const FrameState last = recorded.read(2, united, "the scene");
  EXPECT_LT((last.positions - end.positions).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((last.velocities - end.velocities).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_EQ(last.vonMisesStress.size(), united.elements.rows());
  EXPECT_EQ(last.stress.rows(), united.elements.rows());
  // A probe finds a point of the second body in the second body.
  const Index node = level0.nodeCount + 5;
  const Points3 point = united.nodes.row(node);
  const RunProbe probe = probeRun(dir / "run.pvd", point, {"point"});
  EXPECT_GE(probe.elements[0], level0.elementCount);
  EXPECT_LT((probe.displacements[2].row(0) - (end.positions.row(node) - united.nodes.row(node)))
                .cwiseAbs()
                .maxCoeff(),
            1e-6);
  // Another mesh than the scene's is named.
  expectErrorAt([&] { recorded.read(0, bodyPart(united, recorded.bodies()[0]), "body 0 alone"); },
                (dir / "run.pvd").string(), 0, "records 2 bodies of");
}

// What a scene of several bodies refuses, named by the field.
// A body's surface loads act on its own boundary: a box around both
// bodies selects the first's faces alone, and a face set's node ids count
// from the body's first node.
TEST(SceneRun, SurfaceLoadsActOnTheirBodysOwnFaces) {
  ScratchDir dir;
  const Dataset bunny = loadDataset(kSampleData + "bunny.json");
  const TetMesh level0 = extractLevel(bunny.mesh, 0);
  const BoundaryFaces boundary = boundaryFaces(level0);
  nlohmann::json json = twoBunnies();
  json["bodies"][0]["surface_loads"] = {
      {{"traction", {0, -1, 0}}, {"load_box", {-1e3, -1e3, -1e3, 1e3, 1e3, 1e3}}}};
  const std::string faces =
      std::to_string(boundary.faces(3, 1)) + " " + std::to_string(boundary.faces(3, 2)) + " " +
      std::to_string(boundary.faces(3, 0)) + "\n" + std::to_string(boundary.faces(7, 0)) + " " +
      std::to_string(boundary.faces(7, 1)) + " " + std::to_string(boundary.faces(7, 2)) + "\n";
  json["bodies"][1]["surface_loads"] = {
      {{"pressure", 50}, {"load_faces", dir.write("two.faces", faces).string()}}};
  const SceneRun run = loadScene(parse(json));
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  ASSERT_EQ(spec.parameters.surfaceLoads.size(), 2u);
  const SurfaceLoad& first = spec.parameters.surfaceLoads[0];
  EXPECT_EQ(first.faces.rows(), boundary.faces.rows());
  EXPECT_LT(first.faces.maxCoeff(), level0.nodeCount());
  EXPECT_EQ(first.traction, Eigen::Vector3d(0, -1, 0));
  const SurfaceLoad& second = spec.parameters.surfaceLoads[1];
  ASSERT_EQ(second.faces.rows(), 2);
  const int shift = static_cast<int>(level0.nodeCount());
  EXPECT_EQ(second.faces.row(0), (boundary.faces.row(3).array() + shift).matrix());
  EXPECT_EQ(second.faces.row(1), (boundary.faces.row(7).array() + shift).matrix());
  EXPECT_EQ(second.pressure, 50);

  // Refused: no value, faces both ways, and a face set's line no face.
  nlohmann::json bad = twoBunnies();
  bad["bodies"][1]["surface_loads"] = {{{"load_box", {0, 0, 0, 1, 1, 1}}}};
  EXPECT_EQ(errorText([&] { parse(bad); }),
            "scene.json: /bodies/1/surface_loads/0: give a pressure, a traction or both");
  bad["bodies"][1]["surface_loads"][0]["pressure"] = 1;
  bad["bodies"][1]["surface_loads"][0]["load_faces"] = "x.faces";
  EXPECT_EQ(errorText([&] { parse(bad); }),
            "scene.json: /bodies/1/surface_loads/0: give its faces by load_box or by load_faces, "
            "one of them");
  const std::array<int, 3> inner = innerFace(level0);
  bad["bodies"][1]["surface_loads"][0].erase("load_box");
  bad["bodies"][1]["surface_loads"][0]["load_faces"] =
      dir.write("inner.faces", std::to_string(inner[0]) + " " + std::to_string(inner[1]) + " " +
                                   std::to_string(inner[2]) + "\n")
          .string();
  const SceneRun badRun = loadScene(parse(bad));
  expectErrorAt([&] { resolveRun(badRun.request, badRun.dataset.mesh, badRun.dataset.config); },
                (dir / "inner.faces").string(), 1, "are not a face of the boundary");
}

TEST(SceneRun, SeveralBodiesRefuseWhatTheyCannotShare) {
  const auto refused = [](const auto& edit, const std::string& what) {
    nlohmann::json json = twoBunnies();
    edit(json);
    expectErrorAt(
        [&] {
          const SceneRun run = loadScene(parse(json));
          resolveRun(run.request, run.dataset.mesh, run.dataset.config);
        },
        "scene.json", 0, what);
  };
  refused([](auto& j) { j["bodies"][1]["scenario"] = "sag"; },
          "/bodies/1/scenario: the bodies of a scene of several run free");
  refused([](auto& j) { j["bodies"][1]["contact_points"] = "cage"; },
          "/bodies/1/contact_points: must be /bodies/0's");
  refused([](auto& j) { j["bodies"][1]["held_box"] = {100, 100, 100, 101, 101, 101}; },
          "/bodies/1/held_box: ");
  refused([](auto& j) { j["bodies"][1]["level"] = 7; }, "/bodies/1/level: ");
  nlohmann::json json = twoBunnies();
  json["bodies"][1]["material"]["mass_damping"] = 0.5;
  const SceneRun run = loadScene(parse(json));
  EXPECT_EQ(errorText([&] { resolveRun(run.request, run.dataset.mesh, run.dataset.config); }),
            "/bodies/1: its damping (0.5, 0.01) is not /bodies/0's (0.1, 0.01): mass_damping and "
            "stiffness_damping are one for all the bodies of a run");
}

}  // namespace
}  // namespace tetskin::test
