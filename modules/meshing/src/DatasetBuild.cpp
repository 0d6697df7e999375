// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/DatasetBuild.h"

#include <string>
#include <utility>

#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin {

DatasetBuild buildDatasetFiles(const std::vector<std::filesystem::path>& inputs,
                               const std::filesystem::path& output, const BuildOptions& options,
                               const BuildEvents& events) {
  if (inputs.empty()) throw Error("no input: give at least one surface file");
  DatasetBuild build;
  build.config = datasetConfigPath(output);
  const std::filesystem::path directory = std::filesystem::absolute(build.config).parent_path();
  requireWritableLocation(build.config);  // before the meshing, not after it
  std::vector<SurfaceInput> surfaces;
  for (const std::filesystem::path& path : inputs) {
    SurfaceInput input;
    input.mesh = readSurface(path);
    input.name = path.string();
    input.file =
        std::filesystem::relative(std::filesystem::absolute(path), directory).generic_string();
    if (events.log)
      events.log("read " + path.string() + ": " + std::to_string(input.mesh.vertexCount()) +
                 " vertices, " + std::to_string(input.mesh.triangleCount()) + " triangles");
    surfaces.push_back(std::move(input));
  }
  build.result = buildDataset(std::move(surfaces), options, events);
  // (The writers make the folder only now: bad input or a failed build
  // leaves no empty folder behind.)
  saveDataset(build.config, build.result.dataset);
  return build;
}

}  // namespace tetskin
