// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Model generation from files, wired once for every front end (`tetskin
// build`, Python's tetskin.build): the input surfaces read and named as the
// config will name them, the build, the dataset written.

#include <filesystem>
#include <vector>

#include "tetskin/meshing/ModelBuilder.h"

namespace tetskin {

// Reads the surfaces at `inputs` (levels of detail of one object; the
// config names them relative to its folder), builds the dataset
// (buildDataset) and writes it to `output`'s config (datasetConfigPath:
// OUTPUT.json, .node, .ele), checked writable before the meshing. Logs
// "read PATH: N vertices, M triangles" per input through events.log.
// Throws as readSurface and buildDataset do.
struct DatasetBuild {
  std::filesystem::path config;  // the written config
  BuildResult result;
};
DatasetBuild buildDatasetFiles(const std::vector<std::filesystem::path>& inputs,
                               const std::filesystem::path& output, const BuildOptions& options,
                               const BuildEvents& events = {});

}  // namespace tetskin
