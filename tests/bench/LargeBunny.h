// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The benchmarks' ~109k-element dataset: the bundled bunny at TetGen
// quality 1.2 over three coarser levels, built in the run on every core.

#include <string>

#include "tetskin/meshing/ModelBuilder.h"

namespace tetskin::bench {

// `dataDirectory`: the folder holding bunny.obj (with its trailing slash).
BuildResult buildLargeBunny(const std::string& dataDirectory);

}  // namespace tetskin::bench
