// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SceneRun.h"

#include <map>
#include <memory>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/LoadCurveFile.h"
#include "tetskin/io/NodeList.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin {
namespace {

// Runs `load`; its Error comes back naming the scene file and `pointer`.
template <class Load>
auto inScene(const Scene& scene, const std::string& pointer, Load&& load) {
  try {
    return load();
  } catch (const Error& e) {
    throw Error(scene.file.string(), 0, pointer + ": " + e.what());
  }
}

void requireFile(const Scene& scene, const std::string& pointer,
                 const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw Error(scene.file.string(), 0, pointer + ": " + path.string() + ": no such file");
}

}  // namespace

void place(const ScenePlacement& placement, MultiLevelTetMesh& mesh) {
  const ObstaclePose pose = placement.pose();
  for (Index v = 0; v < mesh.nodes.rows(); ++v)
    mesh.nodes.row(v) = pose.toWorld(mesh.nodes.row(v).transpose()).transpose();
}

void place(const ScenePlacement& placement, SurfaceMesh& surface) {
  const ObstaclePose pose = placement.pose();
  for (Index v = 0; v < surface.positions.rows(); ++v)
    surface.positions.row(v) = pose.toWorld(surface.positions.row(v).transpose()).transpose();
  for (Index v = 0; v < surface.normals.rows(); ++v)
    surface.normals.row(v) = (pose.rotation * surface.normals.row(v).transpose()).transpose();
}

void place(const ScenePlacement& placement, SurfaceBinding& binding) {
  binding.distance *= placement.scale;
}

std::shared_ptr<const ClosedSurfaceDistance> readObstacleShape(const std::filesystem::path& path) {
  return std::make_shared<const ClosedSurfaceDistance>(readSurface(path), path.string());
}

SceneRun loadScene(const Scene& scene) {
  if (scene.bodies.size() != 1)
    throw Error(scene.file.string(), 0, "/bodies: this TetSkin runs one body per scene");
  const SceneBody& body = scene.bodies.front();
  const std::string at = "/bodies/0";
  SceneRun run;
  run.scene = scene;
  requireFile(scene, at + "/dataset", body.dataset);
  run.dataset = inScene(scene, at + "/dataset", [&] { return loadDataset(body.dataset); });
  place(body.placement, run.dataset.mesh);

  std::optional<SurfaceOrBinding> read;
  if (body.surface) {
    requireFile(scene, at + "/surface", *body.surface);
    read = inScene(scene, at + "/surface",
                   [&] { return readSurfaceOrBinding(*body.surface, run.dataset.mesh); });
  }
  const auto levelOf = [&](int given) {
    return inScene(scene, at + "/level", [&] { return resolveLevel(run.dataset.mesh, given); });
  };
  run.level = levelOf(body.level.value_or(kFinestLevel));
  if (read && read->binding) {
    if (body.level && run.level != read->binding->level)
      throw Error(scene.file.string(), 0,
                  at + "/level: " + std::to_string(*body.level) + " is not the level " +
                      body.surface->string() + " is bound to (" +
                      std::to_string(read->binding->level) + "); leave level out to use that");
    run.level = read->binding->level;
  }
  if (read) {
    SceneSurface surface;
    surface.path = *body.surface;
    surface.surface = std::move(read->surface);
    place(body.placement, surface.surface);
    if (read->binding) {
      surface.binding = std::move(*read->binding);
      place(body.placement, surface.binding);
    } else {
      surface.binding = inScene(scene, at + "/surface", [&] {
        return bindSurface(surface.surface, run.dataset.mesh, run.level);
      });
    }
    run.surface = std::move(surface);
  }

  RunRequest& request = run.request;
  request.names = OptionNames::Keys;
  request.datasetName = body.dataset.string();
  request.level = run.level;
  request.scenario = body.scenario;
  request.material = body.material;
  request.up = scene.up;
  request.gravity = scene.gravity;
  request.initialVelocity = body.velocity;
  const Index nodeCount = run.dataset.mesh.levels[static_cast<std::size_t>(run.level)].nodeCount;
  ScenarioParameters& p = request.parameters;
  if (body.fixedNodes)
    p.fixedNodes = inScene(scene, at + "/fixed_nodes",
                           [&] { return readNodeList(*body.fixedNodes, nodeCount); });
  if (body.loads)
    p.loads = inScene(scene, at + "/loads", [&] { return readNodeForces(*body.loads, nodeCount); });
  if (body.loadCurve)
    p.loadCurve =
        inScene(scene, at + "/load_curve", [&] { return readLoadCurve(*body.loadCurve); });
  if (body.loadSeconds) p.loadSeconds = *body.loadSeconds;
  request.fixedBox = body.heldBox;
  if (scene.timeStep) request.settings.timeStep = *scene.timeStep;
  if (scene.floor) {
    request.floorHeight = scene.floor->height;
    if (scene.floor->friction) request.settings.friction = *scene.floor->friction;
    if (scene.floor->stiffness) request.settings.floorStiffness = *scene.floor->stiffness;
  }
  if (body.contactPoints) request.settings.contactPoints = *body.contactPoints;
  if (scene.skinContact) request.settings.skinCollisions = *scene.skinContact;
  request.settings.skinCollisions.self = body.selfContact.value_or(false);

  // One shape per surface file, however often it is placed.
  std::map<std::filesystem::path, std::shared_ptr<const ClosedSurfaceDistance>> shapes;
  for (const SceneObstacle& o : scene.obstacles) {
    requireFile(scene, o.pointer + "/surface", o.surface);
    std::shared_ptr<const ClosedSurfaceDistance>& shape = shapes[o.surface];
    if (!shape)
      shape = inScene(scene, o.pointer + "/surface", [&] { return readObstacleShape(o.surface); });
    Obstacle obstacle;
    obstacle.name = scene.file.string() + ": " + o.pointer;
    obstacle.shape = shape;
    obstacle.placement = o.placement.pose();
    obstacle.motion = o.motion;
    obstacle.staticFriction = o.staticFriction;
    obstacle.kineticFriction = o.kineticFriction;
    obstacle.stiffness = o.stiffness;
    request.settings.obstacles.push_back(std::move(obstacle));
  }
  run.steps = scene.steps.value_or(static_cast<int>(recording_option::kSteps.defaultValue));
  return run;
}

}  // namespace tetskin
