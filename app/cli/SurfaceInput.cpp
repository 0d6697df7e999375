// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SurfaceInput.h"

#include <vtkPolyData.h>

#include <string>
#include <utility>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {

SurfaceInput readSurfaceInput(const std::filesystem::path& path, const MultiLevelTetMesh& dataset) {
  SurfaceInput input;
  input.path = path;
  if (lowerExtension(path) != ".vtp") {
    input.surface = readSurface(path);
    return input;
  }
  // (Read once: a plain .vtp is what readSurface makes of it.)
  const vtkSmartPointer<vtkPolyData> data = readVtp(path);
  if (!isBinding(data)) {
    input.surface = fromVtkPolyData(data, path.string());
    return input;
  }
  BoundSurface bound = bindingFromPolyData(data, path.string(), dataset);
  input.surface = std::move(bound.surface);
  input.binding = std::move(bound.binding);
  return input;
}

int commandLevel(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int levelOption,
                 bool levelGiven) {
  if (!input.binding) return resolveLevel(dataset, levelOption);
  const int bound = input.binding->level;
  if (levelGiven && resolveLevel(dataset, levelOption) != bound)
    throw Error("--level " + std::to_string(levelOption) + ": " + input.path.string() +
                " is bound to level " + std::to_string(bound) +
                "; leave --level out to use that level");
  return bound;
}

SurfaceBinding bindingAt(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int level) {
  return input.binding ? *input.binding : bindSurface(input.surface, dataset, level);
}

}  // namespace tetskin::cli
