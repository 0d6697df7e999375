// SPDX-License-Identifier: AGPL-3.0-or-later
// Scenes (SceneFile.h, SceneRun.h): the bundled scene read with its paths
// relative to it; bad scenes refused naming the file and the field; and
// bodies dropped into a bowl and onto a sphere come to rest on their skin,
// its deepest vertex less than 0.5% of the body's diagonal inside (measured
// against the exact sphere, not the contact's own distances), the contact
// forces equal to the weight within 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "ExpectError.h"
#include "SampleData.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/session/SimulationSession.h"

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
  expect([](auto& j) { j["bodies"].push_back(j["bodies"][0]); },
         "/bodies: holds 2 bodies; this TetSkin runs one body per scene");
  expect([](auto& j) { j.erase("bodies"); }, "/bodies: is missing");
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

}  // namespace
}  // namespace tetskin::test
