// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SceneFlags.h"

#include <string>

#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"

namespace tetskin::cli {

SceneRun loadSceneWithFlags(const std::filesystem::path& path, std::optional<int> level,
                            const std::filesystem::path& surface) {
  Scene scene = readScene(path);
  if (scene.bodies.size() > 1 && (level || !surface.empty()))
    throw Error(path.string() + ": holds " + std::to_string(scene.bodies.size()) +
                " bodies; each takes its level and surface from the scene, not from " +
                kLevelOption.flag + " or --surface");
  SceneBody& body = scene.bodies.front();
  if (level) body.level = *level;
  if (!surface.empty()) body.surface = std::filesystem::absolute(surface);
  return loadScene(scene);
}

}  // namespace tetskin::cli
