// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SceneFile.h"

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <limits>

#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/io/JsonFields.h"
#include "tetskin/simulation/Scenario.h"

namespace tetskin {
namespace {

using nlohmann::json;
constexpr double kLargest = std::numeric_limits<double>::max();

Eigen::Quaterniond rotationOf(const Eigen::Vector3d& degrees) {
  const Eigen::Vector3d r = degrees * M_PI / 180.0;
  // About x first, then y, then z: R = Rz Ry Rx.
  return Eigen::Quaterniond(Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()));
}

// A value checked against its schema option's range.
double schemaNumber(const JsonFields& f, const NumberOption& option) {
  const double value = f.anyNumber(option.key);
  if (const auto problem = option.problem(value)) f.fail(f.where(option.key), *problem);
  return value;
}

std::filesystem::path pathField(const JsonFields& f, const char* key,
                                const std::filesystem::path& directory) {
  const std::filesystem::path given = f.string(key);
  return given.is_absolute() ? given : directory / given;
}

ScenePlacement readPlacement(const JsonFields& f) {
  ScenePlacement p;
  f.optional("translate");
  f.optional("rotate");
  f.optional("scale");
  if (f.has("translate")) p.translate = f.vector3("translate");
  if (f.has("rotate")) p.rotate = f.vector3("rotate");
  if (f.has("scale")) p.scale = f.number("scale", 0, kLargest, true);
  return p;
}

// A box field, [xmin, ymin, zmin, xmax, ymax, zmax] with min <= max.
BoundingBox boxField(const JsonFields& f, const char* key) {
  const Eigen::VectorXd numbers = f.numbers(key, 6);
  const BoundingBox box{numbers.head<3>(), numbers.tail<3>()};
  if (box.empty())
    f.fail(f.where(key), "must be [xmin, ymin, zmin, xmax, ymax, zmax] with min <= max");
  return box;
}

// One of a body's surface_loads: {"pressure": P, "traction": [X, Y, Z],
// "load_box": [xmin, ymin, zmin, xmax, ymax, zmax] or "load_faces": FILE}.
SurfaceLoadRequest readSurfaceLoad(const json& value, const std::string& pointer,
                                   const std::string& file,
                                   const std::filesystem::path& directory) {
  using namespace scenario_option;
  JsonFields f(value, pointer, file);
  SurfaceLoadRequest load;
  load.name = file + ": " + pointer;
  for (const char* key : {kPressure.key, kTraction.key, kLoadBox.key, kLoadFaces.key})
    f.optional(key);
  if (!f.has(kPressure.key) && !f.has(kTraction.key))
    f.fail(pointer, "give a pressure, a traction or both");
  if (f.has(kPressure.key)) load.pressure = schemaNumber(f, kPressure);
  if (f.has(kTraction.key)) load.traction = f.vector3(kTraction.key);
  if (f.has(kLoadBox.key) == f.has(kLoadFaces.key))
    f.fail(pointer, std::string("give its faces by ") + kLoadBox.key + " or by " + kLoadFaces.key +
                        ", one of them");
  if (f.has(kLoadBox.key)) load.box = boxField(f, kLoadBox.key);
  if (f.has(kLoadFaces.key)) load.faceFile = pathField(f, kLoadFaces.key, directory);
  f.rejectUnknown();
  return load;
}

template <SchemaEnum E>
E enumField(const JsonFields& f, const char* key) {
  const std::string name = f.string(key);
  const std::optional<E> value = parseName<E>(name);
  if (!value)
    f.fail(f.where(key), "must be one of " + listed(namesOf<E>()) + ", found \"" + name + "\"");
  return *value;
}

SceneBody readBody(const json& value, const std::string& pointer, const std::string& file,
                   const std::filesystem::path& directory) {
  JsonFields f(value, pointer, file);
  SceneBody body;
  body.dataset = pathField(f, "dataset", directory);
  for (const char* key : {"level", "surface", "velocity", "held_box", "material", "scenario",
                          simulation_option::kContactPoints.key, "self_contact", "fixed_nodes",
                          "loads", "load_curve", "load_seconds", "surface_loads"})
    f.optional(key);
  if (f.has("level")) body.level = static_cast<int>(f.integer("level", -1000000, 1000000));
  if (f.has("surface")) body.surface = pathField(f, "surface", directory);
  body.placement = readPlacement(f);
  if (f.has("velocity")) body.velocity = f.vector3("velocity");
  if (f.has("held_box")) body.heldBox = boxField(f, "held_box");
  if (f.has("material")) {
    JsonFields m(f.get("material"), f.where("material"), file);
    for (const MaterialField& field : materialFields()) {
      m.optional(field.option->key);
      if (m.has(field.option->key))
        body.material.set(*field.option, schemaNumber(m, *field.option));
    }
    m.rejectUnknown();
  }
  if (f.has("scenario")) {
    body.scenario = f.string("scenario");
    if (!isScenario(body.scenario))
      f.fail(f.where("scenario"),
             "must be one of " + listed(scenarioNames()) + ", found \"" + body.scenario + "\"");
  }
  if (f.has(simulation_option::kContactPoints.key))
    body.contactPoints = enumField<ContactPoints>(f, simulation_option::kContactPoints.key);
  if (f.has("self_contact")) body.selfContact = f.boolean("self_contact");
  if (f.has("fixed_nodes")) body.fixedNodes = pathField(f, "fixed_nodes", directory);
  if (f.has("loads")) body.loads = pathField(f, "loads", directory);
  if (f.has("load_curve")) body.loadCurve = pathField(f, "load_curve", directory);
  if (f.has("load_seconds")) body.loadSeconds = schemaNumber(f, scenario_option::kLoadSeconds);
  if (f.has("surface_loads")) {
    const json& loads = f.get("surface_loads");
    if (!loads.is_array() || loads.empty())
      f.fail(f.where("surface_loads"), "must be a non-empty array");
    for (std::size_t k = 0; k < loads.size(); ++k)
      body.surfaceLoads.push_back(readSurfaceLoad(
          loads[k], f.where("surface_loads") + "/" + std::to_string(k), file, directory));
  }
  f.rejectUnknown();
  return body;
}

// "friction" (both coefficients), or "static_friction" and
// "kinetic_friction" (mu_k <= mu_s), over the defaults passed in.
void readFriction(const JsonFields& f, double& staticFriction, double& kineticFriction) {
  if (f.has("friction")) {
    if (f.has("static_friction") || f.has("kinetic_friction"))
      f.fail(f.where("friction"),
             "give friction, or static_friction and kinetic_friction, not both");
    staticFriction = kineticFriction = f.number("friction", 0, kLargest);
  }
  if (f.has("static_friction")) staticFriction = f.number("static_friction", 0, kLargest);
  if (f.has("kinetic_friction")) kineticFriction = f.number("kinetic_friction", 0, kLargest);
  if (kineticFriction > staticFriction)
    f.fail(f.where("kinetic_friction"), "must not exceed static_friction (" +
                                            formatNumber(staticFriction) + "), found " +
                                            formatNumber(kineticFriction));
}

SceneObstacle readObstacle(const json& value, const std::string& pointer, const std::string& file,
                           const std::filesystem::path& directory) {
  JsonFields f(value, pointer, file);
  SceneObstacle o;
  o.pointer = pointer;
  o.surface = pathField(f, "surface", directory);
  o.placement = readPlacement(f);
  for (const char* key : {"friction", "static_friction", "kinetic_friction", "stiffness", "motion"})
    f.optional(key);
  readFriction(f, o.staticFriction, o.kineticFriction);
  if (f.has("stiffness")) o.stiffness = f.number("stiffness", 0, kLargest);
  if (f.has("motion")) {
    const json& keys = f.get("motion");
    if (!keys.is_array() || keys.empty()) f.fail(f.where("motion"), "must be a non-empty array");
    for (std::size_t k = 0; k < keys.size(); ++k) {
      JsonFields key(keys[k], f.where("motion") + "/" + std::to_string(k), file);
      PoseKey pose;
      pose.time = key.anyNumber("time");
      if (!o.motion.empty() && pose.time <= o.motion.back().time)
        key.fail(key.where("time"), "must be later than the key before's (" +
                                        formatNumber(o.motion.back().time) + ")");
      key.optional("translate");
      key.optional("rotate");
      if (key.has("translate")) pose.translation = key.vector3("translate");
      if (key.has("rotate")) pose.rotation = rotationOf(key.vector3("rotate"));
      key.rejectUnknown();
      o.motion.push_back(pose);
    }
  }
  f.rejectUnknown();
  return o;
}

}  // namespace

ObstaclePose ScenePlacement::pose() const {
  ObstaclePose p;
  p.translation = translate;
  p.rotation = rotationOf(rotate);
  p.scale = scale;
  return p;
}

Scene parseScene(const json& root, const std::filesystem::path& file,
                 const std::filesystem::path& directory) {
  const std::string name = file.string();
  JsonFields top(root, "", name);
  if (top.string("format") != kSceneFormat)
    top.fail("/format", std::string("must be \"") + kSceneFormat + "\"");
  const long long version = top.integer("version", 1, 1000);
  if (version != kSceneFormatVersion)
    top.fail("/version", "version " + std::to_string(version) +
                             " is not supported (this TetSkin reads version " +
                             std::to_string(kSceneFormatVersion) + ")");
  Scene scene;
  scene.file = file;
  for (const char* key :
       {"time_step", "steps", "gravity", "up", "floor", "skin_contact", "obstacles"})
    top.optional(key);
  if (top.has("time_step")) scene.timeStep = schemaNumber(top, simulation_option::kTimeStep);
  if (top.has("steps"))
    scene.steps = static_cast<int>(top.integer("steps", 0, std::numeric_limits<int>::max()));
  if (top.has("gravity")) scene.gravity = top.vector3("gravity");
  if (top.has("up")) scene.up = enumField<UpAxis>(top, "up");
  if (top.has("floor")) {
    JsonFields f(top.get("floor"), "/floor", name);
    SceneFloor floor;
    f.optional("height");
    f.optional(simulation_option::kFriction.key);
    f.optional("stiffness");
    if (f.has("height")) floor.height = f.anyNumber("height");
    if (f.has(simulation_option::kFriction.key))
      floor.friction = schemaNumber(f, simulation_option::kFriction);
    if (f.has("stiffness")) floor.stiffness = f.number("stiffness", 0, kLargest);
    f.rejectUnknown();
    scene.floor = floor;
  }
  if (top.has("skin_contact")) {
    JsonFields f(top.get("skin_contact"), "/skin_contact", name);
    SkinCollisions skins;
    for (const char* key :
         {"thickness", "stiffness", "friction", "static_friction", "kinetic_friction"})
      f.optional(key);
    if (f.has("thickness")) skins.thickness = f.number("thickness", 0, kLargest);
    if (f.has("stiffness")) skins.stiffness = f.number("stiffness", 0, kLargest);
    readFriction(f, skins.staticFriction, skins.kineticFriction);
    f.rejectUnknown();
    scene.skinContact = skins;
  }
  const json& bodies = top.get("bodies");
  if (!bodies.is_array() || bodies.empty()) top.fail("/bodies", "must be a non-empty array");
  for (std::size_t k = 0; k < bodies.size(); ++k)
    scene.bodies.push_back(readBody(bodies[k], "/bodies/" + std::to_string(k), name, directory));
  if (top.has("obstacles")) {
    const json& obstacles = top.get("obstacles");
    if (!obstacles.is_array()) top.fail("/obstacles", "must be an array");
    for (std::size_t k = 0; k < obstacles.size(); ++k)
      scene.obstacles.push_back(
          readObstacle(obstacles[k], "/obstacles/" + std::to_string(k), name, directory));
  }
  top.rejectUnknown();
  return scene;
}

Scene readScene(const std::filesystem::path& path) {
  const std::filesystem::path directory =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  return parseScene(readJsonFile(path), path, directory);
}

bool isSceneFile(const std::filesystem::path& path) {
  if (path.extension() != ".json") return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  const json root = json::parse(in, nullptr, /*allow_exceptions=*/false);
  return root.is_object() && root.contains("format") && root["format"] == kSceneFormat;
}

}  // namespace tetskin
