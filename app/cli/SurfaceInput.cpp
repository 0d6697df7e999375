// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SurfaceInput.h"

#include <cstdio>
#include <string>
#include <utility>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/vtkio/BindingFile.h"

namespace tetskin::cli {

SurfaceInput readSurfaceInput(const std::filesystem::path& path, const MultiLevelTetMesh& dataset) {
  SurfaceOrBinding read = readSurfaceOrBinding(path, dataset);
  warnOfNormalGaps(path, read.surface);
  return {path, std::move(read.surface), std::move(read.binding)};
}

void warnOfNormalGaps(const std::filesystem::path& path, const SurfaceMesh& surface) {
  if (const NormalGaps gaps = normalGaps(surface); !gaps.empty())
    std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), describe(gaps).c_str());
}

BindingSummary warnOfMisfit(const std::filesystem::path& path, const SurfaceMesh& surface,
                            const SurfaceBinding& binding, const MultiLevelTetMesh& dataset) {
  BindingSummary summary = summarizeBinding(binding, boundingBox(surface).diagonal());
  if (const std::string warning = misfitWarning(summary, dataset, binding.level); !warning.empty())
    std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), warning.c_str());
  return summary;
}

int commandLevel(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int levelOption,
                 bool levelGiven) {
  if (!input.binding) return resolveLevel(dataset, levelOption);
  const int bound = input.binding->level;
  if (levelGiven && resolveLevel(dataset, levelOption) != bound)
    throw Error(std::string(kLevelOption.flag) + " " + std::to_string(levelOption) + ": " +
                input.path.string() + " is bound to level " + std::to_string(bound) +
                "; leave --level out to use that level");
  return bound;
}

SurfaceBinding bindingAt(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int level) {
  if (input.binding) return *input.binding;
  SurfaceBinding binding = bindSurface(input.surface, dataset, level);
  warnOfMisfit(input.path, input.surface, binding, dataset);
  return binding;
}

}  // namespace tetskin::cli
