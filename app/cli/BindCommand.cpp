// SPDX-License-Identifier: AGPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "OptionChecks.h"
#include "SurfaceInput.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BindingSummary.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::cli {
namespace {

struct BindArgs {
  std::filesystem::path dataset, surface, output;
  int level = kFinestLevel;
  std::string method = toString(BindingOptions{}.method),
              offset = toString(BindingOptions{}.offset);
};

void run(const BindArgs& a, const CLI::App& cmd) {
  if (fromName<BindingMethod>(a.method) == BindingMethod::Embed &&
      cmd.count(binding_option::kOffset.flag) > 0)
    throw Error(std::string(binding_option::kOffset.flag) +
                ": applies to the closest and seed methods, not to embed (an embedded vertex is "
                "its tetrahedron's barycentric combination, with no offset)");
  requireNotAnInput(a.output, {a.dataset, a.surface});
  const Dataset dataset = loadDataset(a.dataset);
  const int level = resolveLevel(dataset.mesh, a.level);
  BoundSurface bound;
  bound.surface = readSurface(a.surface);
  warnOfNormalGaps(a.surface, bound.surface);
  BindingOptions options;
  options.method = fromName<BindingMethod>(a.method);
  options.offset = fromName<OffsetMode>(a.offset);
  const auto start = std::chrono::steady_clock::now();
  bound.binding = bindSurface(bound.surface, dataset.mesh, level, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bound.surface.normals = vertexNormals(bound.surface.positions, bound.surface.triangles);
  bound.dataset = a.dataset.generic_string();
  writeBinding(a.output, bound);
  std::fputs(formatSummary(warnOfMisfit(a.surface, bound.surface, bound.binding, dataset.mesh),
                           bound.binding)
                 .c_str(),
             stdout);
  // A level meshed from a wrap lies off the input by the wrap's distances;
  // the surface's own distances above are to that level.
  if (const std::optional<LevelWrap>& wrap =
          dataset.config.levels[static_cast<std::size_t>(level)].source.wrap)
    std::printf(
        "  wrapped level:      %s was alpha-wrapped for it: %s; vertices in the input's "
        "holes and gaps bind to their closest boundary triangle\n",
        dataset.config.levels[static_cast<std::size_t>(level)].source.input.c_str(),
        describe(*wrap).c_str());
  if (const std::optional<LevelFidelity>& fidelity =
          dataset.config.levels[static_cast<std::size_t>(level)].fidelity)
    std::printf("  level vs its input: %s\n", describe(*fidelity).c_str());
  std::printf("  time:               %.3f s\nwrote %s\n", seconds, a.output.c_str());
}

}  // namespace

void addBindCommand(CLI::App& app) {
  auto a = std::make_shared<BindArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bind", "Bind a surface (OBJ/PLY/STL/VTP) to a dataset level's boundary; writes a .vtp");
  cmd->add_option("DATASET", a->dataset, kDatasetHelp)->required()->check(CLI::ExistingFile);
  cmd->add_option("SURFACE", a->surface, "surface to bind")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "binding file (.vtp)")
      ->required()
      ->check(fileEnding(".vtp"));
  cmd->add_option(kLevelOption.flag, a->level, kLevelOption.help)->check(anyWholeNumber());
  addEnumOption(*cmd, binding_option::kMethod, a->method);
  addEnumOption(*cmd, binding_option::kOffset, a->offset);
  addCompressOption(*cmd);
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
