// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A scene file (.json, format "tetskin-scene"): the bodies, the obstacles
// with their placement, motion and friction, the floor, gravity, the time
// step and the step count; as read, paths resolved against the scene's
// folder and every value checked, before anything is loaded (SceneRun.h
// loads it). The schema is doc/user/contact-and-scenes.md's. Errors name
// the scene file and the field's JSON pointer
// ("bowl.json: /obstacles/0/scale: must lie in (0, inf), found -1").

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/Geometry.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/session/SurfaceLoadSelection.h"
#include "tetskin/simulation/Obstacle.h"

namespace tetskin {

inline constexpr const char* kSceneFormat = "tetskin-scene";
inline constexpr int kSceneFormatVersion = 1;

// x -> translate + scale * R x, R the rotation by rotate's degrees about x,
// then y, then z.
struct ScenePlacement {
  Eigen::Vector3d translate = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotate = Eigen::Vector3d::Zero();  // degrees about x, y, z, in that order
  double scale = 1;
  ObstaclePose pose() const;
};

struct SceneBody {
  std::filesystem::path dataset;                       // absolute (resolved)
  std::optional<int> level;                            // nullopt: the finest, or the binding's
  std::optional<std::filesystem::path> surface;        // a surface or a binding from `tetskin bind`
  ScenePlacement placement;                            // of the dataset and the surface alike
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // at the start, m/s
  std::optional<BoundingBox> heldBox;                  // in the placed body's (world) coordinates
  MaterialOverrides material;                          // over the dataset config's
  std::string scenario = "free";
  std::optional<ContactPoints> contactPoints;  // nullopt: the schema's default
  std::optional<bool> selfContact;             // nullopt: SkinCollisions' default (off)
  std::optional<std::filesystem::path> fixedNodes, loads, loadCurve;
  std::optional<double> loadSeconds;
  // Pressures and tractions on the body's boundary (each named by its
  // pointer; a box in the placed body's coordinates, a face set's node ids
  // the level's).
  std::vector<SurfaceLoadRequest> surfaceLoads;
};

struct SceneObstacle {
  std::filesystem::path surface;  // absolute (resolved); a closed surface
  ScenePlacement placement;
  std::vector<PoseKey> motion;  // translation and rotation per key; the scale is placement's
  double staticFriction = 0.5, kineticFriction = 0.4, stiffness = 0;
  std::string pointer;  // "/obstacles/2": where the file says it, for errors
};

struct SceneFloor {
  double height = 0;                // along the up axis
  std::optional<double> friction;   // nullopt: the schema's default
  std::optional<double> stiffness;  // nullopt: automatic
};

struct Scene {
  std::filesystem::path file;  // as given: names the scene in errors
  std::optional<double> timeStep;
  std::optional<int> steps;
  std::optional<Eigen::Vector3d> gravity;  // nullopt: standard gravity down the up axis
  std::optional<UpAxis> up;                // nullopt: the dataset config's
  std::optional<SceneFloor> floor;
  // The skins' contact with each other and themselves (its `self` unused:
  // each body's self_contact says); nullopt: SkinCollisions' defaults.
  std::optional<SkinCollisions> skinContact;
  std::vector<SceneBody> bodies;  // at least one
  std::vector<SceneObstacle> obstacles;
};

// The scene `root` describes, paths relative to `directory`; `file` names
// it in errors. Throws Error naming the file and the field.
Scene parseScene(const nlohmann::json& root, const std::filesystem::path& file,
                 const std::filesystem::path& directory);
// The scene file at `path`.
Scene readScene(const std::filesystem::path& path);
// Whether `path` is a .json whose "format" is "tetskin-scene" (a dataset
// config says "tetskin-dataset"); false for anything unreadable.
bool isSceneFile(const std::filesystem::path& path);

}  // namespace tetskin
