// SPDX-License-Identifier: AGPL-3.0-or-later
#include "LargeBunny.h"

#include <algorithm>
#include <thread>

#include "tetskin/io/ObjFormat.h"

namespace tetskin::bench {

BuildResult buildLargeBunny(const std::string& dataDirectory) {
  BuildOptions options;
  options.decimate = true;
  options.levels = 4;
  options.minElements = 600;
  options.maxElements = 100000;
  options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return buildDataset({{"bunny.obj", readObj(dataDirectory + "bunny.obj"), ""}}, options);
}

}  // namespace tetskin::bench
