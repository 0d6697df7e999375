// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A command's scene (simulate, render): the scene file loaded (SceneRun.h)
// with the command line's --level and --surface over its body's, which a
// scene of several bodies refuses (each body's level and skin are its own).

#include <filesystem>
#include <optional>

#include "tetskin/session/SceneRun.h"

namespace tetskin::cli {

// `level`: --level's value when given; `surface`: --surface's (empty when
// not given). Throws Error naming the scene for either with several
// bodies, and what loadScene throws.
SceneRun loadSceneWithFlags(const std::filesystem::path& scene, std::optional<int> level,
                            const std::filesystem::path& surface);

}  // namespace tetskin::cli
