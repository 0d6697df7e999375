// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SceneRun.h"

#include <map>
#include <memory>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/BodyUnion.h"
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

namespace {

// A scene body's dataset (placed), level and surface (placed and bound).
struct LoadedBody {
  Dataset dataset;
  int level = 0;
  std::optional<SceneSurface> surface;
};

LoadedBody loadBody(const Scene& scene, std::size_t k) {
  const SceneBody& body = scene.bodies[k];
  const std::string at = "/bodies/" + std::to_string(k);
  LoadedBody loaded;
  requireFile(scene, at + "/dataset", body.dataset);
  loaded.dataset = inScene(scene, at + "/dataset", [&] { return loadDataset(body.dataset); });
  place(body.placement, loaded.dataset.mesh);

  std::optional<SurfaceOrBinding> read;
  if (body.surface) {
    requireFile(scene, at + "/surface", *body.surface);
    read = inScene(scene, at + "/surface",
                   [&] { return readSurfaceOrBinding(*body.surface, loaded.dataset.mesh); });
  }
  loaded.level = inScene(scene, at + "/level", [&] {
    return resolveLevel(loaded.dataset.mesh, body.level.value_or(kFinestLevel));
  });
  if (read && read->binding) {
    if (body.level && loaded.level != read->binding->level)
      throw Error(scene.file.string(), 0,
                  at + "/level: " + std::to_string(*body.level) + " is not the level " +
                      body.surface->string() + " is bound to (" +
                      std::to_string(read->binding->level) + "); leave level out to use that");
    loaded.level = read->binding->level;
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
        return bindSurface(surface.surface, loaded.dataset.mesh, loaded.level);
      });
    }
    loaded.surface = std::move(surface);
  }
  return loaded;
}

// The scene's values that are the run's, not a body's: the time step,
// gravity, up axis, floor and the skins' contact.
void applySceneSettings(const Scene& scene, RunRequest& request) {
  request.names = OptionNames::Keys;
  request.up = scene.up;
  request.gravity = scene.gravity;
  if (scene.timeStep) request.settings.timeStep = *scene.timeStep;
  if (scene.floor) {
    request.floorHeight = scene.floor->height;
    if (scene.floor->friction) request.settings.friction = *scene.floor->friction;
    if (scene.floor->stiffness) request.settings.floorStiffness = *scene.floor->stiffness;
  }
  if (scene.skinContact) request.settings.skinCollisions = *scene.skinContact;
  request.settings.skinCollisions.self = false;
}

// Body k's held nodes (its held box's too, if `heldBoxToo`), loads and
// load curve, its nodes numbered from `firstNode` in a level of
// `levelNodes` nodes: added to `p`. `loadedBody`: the first body whose
// load curve or seconds were taken, if any.
void addBodyConditions(const Scene& scene, std::size_t k, const Points3& restNodes, Index firstNode,
                       Index levelNodes, bool heldBoxToo, ScenarioParameters& p,
                       std::optional<std::size_t>& loadedBody) {
  const SceneBody& body = scene.bodies[k];
  const std::string at = "/bodies/" + std::to_string(k);
  const Index nodeCount = restNodes.rows();
  std::vector<int> held;
  if (body.fixedNodes)
    held = inScene(scene, at + "/fixed_nodes",
                   [&] { return readNodeList(*body.fixedNodes, nodeCount); });
  if (body.heldBox && heldBoxToo)
    held = inScene(scene, at + "/held_box",
                   [&] { return fixedWithNodesInBox(held, restNodes, *body.heldBox); });
  for (int node : held) p.fixedNodes.push_back(node + static_cast<int>(firstNode));
  if (body.loads) {
    const Points3 loads =
        inScene(scene, at + "/loads", [&] { return readNodeForces(*body.loads, nodeCount); });
    if (p.loads.rows() == 0) p.loads = Points3::Zero(levelNodes, 3);
    p.loads.middleRows(firstNode, nodeCount) += loads;
  }
  if (!body.loadCurve && !body.loadSeconds) return;
  // One curve and one release time scale every load of a run.
  if (loadedBody) {
    const SceneBody& first = scene.bodies[*loadedBody];
    if (first.loadCurve != body.loadCurve || first.loadSeconds != body.loadSeconds)
      throw Error(scene.file.string(), 0,
                  at + ": its load_curve and load_seconds must be /bodies/" +
                      std::to_string(*loadedBody) +
                      "'s: one curve and release time scale all the loads of a scene");
    return;
  }
  loadedBody = k;
  if (body.loadCurve)
    p.loadCurve =
        inScene(scene, at + "/load_curve", [&] { return readLoadCurve(*body.loadCurve); });
  if (body.loadSeconds) p.loadSeconds = *body.loadSeconds;
}

// A scene of one body: its dataset and level as they are.
void loadOneBody(const Scene& scene, SceneRun& run) {
  const SceneBody& body = scene.bodies.front();
  LoadedBody loaded = loadBody(scene, 0);
  run.dataset = std::move(loaded.dataset);
  run.level = loaded.level;
  run.surface = std::move(loaded.surface);
  RunRequest& request = run.request;
  request.datasetName = body.dataset.string();
  request.level = run.level;
  request.scenario = body.scenario;
  request.material = body.material;
  request.initialVelocity = body.velocity;
  const LevelRange& level = run.dataset.mesh.levels[static_cast<std::size_t>(run.level)];
  std::optional<std::size_t> loadedBody;
  addBodyConditions(scene, 0, run.dataset.mesh.nodes.middleRows(level.firstNode, level.nodeCount),
                    0, level.nodeCount, /*heldBoxToo=*/false, request.parameters, loadedBody);
  // (The held box stays a box: the front ends show and edit it as one.)
  request.fixedBox = body.heldBox;
  request.surfaceLoads = body.surfaceLoads;
  if (body.contactPoints) request.settings.contactPoints = *body.contactPoints;
  request.settings.skinCollisions.self = body.selfContact.value_or(false);
}

// A scene of several bodies: their levels and skins united (BodyUnion.h)
// into one level and one skin, the run's bodies.
void loadBodies(const Scene& scene, SceneRun& run) {
  std::vector<DatasetConfig> configs;
  std::vector<TetMesh> meshes;
  std::vector<SceneSurface> skins;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const SceneBody& body = scene.bodies[k];
    const std::string at = "/bodies/" + std::to_string(k);
    if (body.scenario != "free")
      throw Error(scene.file.string(), 0,
                  at +
                      "/scenario: the bodies of a scene of several run free (hold nodes with "
                      "held_box or fixed_nodes), found \"" +
                      body.scenario + "\"");
    const SceneBody& first = scene.bodies.front();
    if (body.contactPoints != first.contactPoints)
      throw Error(scene.file.string(), 0,
                  at + "/" + simulation_option::kContactPoints.key +
                      ": must be /bodies/0's: the bodies of a scene meet the obstacles alike");
    LoadedBody one = loadBody(scene, k);
    TetMesh mesh = extractLevel(one.dataset.mesh, one.level);
    const LevelRange& level = one.dataset.mesh.levels[static_cast<std::size_t>(one.level)];
    SceneSurface skin;
    if (one.surface) {
      skin = std::move(*one.surface);
    } else {
      // Without a surface the level's boundary is the body's skin.
      skin.surface = boundarySurface(mesh);
      skin.binding = inScene(
          scene, at, [&] { return bindSurface(skin.surface, one.dataset.mesh, one.level); });
    }
    // The binding in the level's own numbering, as the union takes it: the
    // level is the dataset's part as a body is the union's.
    BodyRange levelPart;
    levelPart.firstNode = level.firstNode;
    levelPart.nodeCount = level.nodeCount;
    levelPart.firstElement = level.firstElement;
    levelPart.elementCount = level.elementCount;
    levelPart.vertexCount = skin.binding.vertexCount();
    skin.binding = bodyPart(skin.binding, levelPart);
    configs.push_back(std::move(one.dataset.config));
    meshes.push_back(std::move(mesh));
    skins.push_back(std::move(skin));
  }
  std::vector<BodyParts> parts;
  for (std::size_t k = 0; k < meshes.size(); ++k)
    parts.push_back({&meshes[k], &skins[k].surface, &skins[k].binding});
  BodyUnion united = inScene(scene, "/bodies", [&] { return uniteBodies(parts); });

  run.dataset.config = configs.front();
  run.dataset.mesh = std::move(united.mesh);
  run.level = 0;
  SceneSurface skin;
  skin.path = scene.file;
  skin.surface = std::move(united.skin);
  skin.binding = std::move(united.binding);
  run.surface = std::move(skin);

  RunRequest& request = run.request;
  request.datasetName = scene.file.string();
  request.level = 0;
  request.scenario = "free";
  const Index levelNodes = run.dataset.mesh.nodes.rows();
  std::optional<std::size_t> loadedBody;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const SceneBody& body = scene.bodies[k];
    const BodyRange& range = united.bodies[k];
    RunBody& runBody = request.bodies.emplace_back();
    runBody.name = "/bodies/" + std::to_string(k);
    runBody.range = range;
    runBody.material = inScene(scene, runBody.name + "/material", [&] {
      return body.material.over(configs[k].elasticity, OptionNames::Keys);
    });
    runBody.velocity = body.velocity;
    runBody.selfContact = body.selfContact.value_or(false);
    addBodyConditions(scene, k, meshes[k].nodes, range.firstNode, levelNodes,
                      /*heldBoxToo=*/true, request.parameters, loadedBody);
    for (SurfaceLoadRequest load : body.surfaceLoads) {
      load.firstNode = range.firstNode;
      load.nodeCount = range.nodeCount;
      request.surfaceLoads.push_back(std::move(load));
    }
  }
  if (scene.bodies.front().contactPoints)
    request.settings.contactPoints = *scene.bodies.front().contactPoints;
}

}  // namespace

SceneRun loadScene(const Scene& scene) {
  if (scene.bodies.empty()) throw Error(scene.file.string(), 0, "/bodies: holds no body");
  SceneRun run;
  run.scene = scene;
  applySceneSettings(scene, run.request);
  if (scene.bodies.size() == 1)
    loadOneBody(scene, run);
  else
    loadBodies(scene, run);

  RunRequest& request = run.request;
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
