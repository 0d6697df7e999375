// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct DeformArgs {
  std::filesystem::path dataset, binding, positions, output;
};

Points3 readPositions(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  if (extension == ".node") return readNode(path).points;
  if (extension == ".vtu") return fromVtkUnstructuredGrid(readVtu(path), path.string()).nodes;
  throw Error(path.string(), 0, "positions must be a .node file or a .vtu with deformed points");
}

void run(const DeformArgs& a) {
  requireNotAnInput(a.output, {a.dataset, a.binding, a.positions});
  const Dataset dataset = loadDataset(a.dataset);
  BoundSurface bound = readBinding(a.binding, dataset.mesh);
  const int level = bound.binding.level;
  const Points3 control =
      datasetPositions(dataset.mesh, level, readPositions(a.positions), a.positions.string());
  SurfaceDeformer deformer(bound.surface, bound.binding, dataset.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(control, positions, normals);
  bound.deformed = DeformedState{positions, normals};
  bound.dataset = a.dataset.generic_string();  // the one its ids were checked against
  writeBinding(a.output, bound);
  std::printf("wrote %s (%lld vertices deformed by %s)\n", a.output.c_str(),
              static_cast<long long>(positions.rows()), a.positions.c_str());
}

}  // namespace

void addDeformCommand(CLI::App& app) {
  auto a = std::make_shared<DeformArgs>();
  CLI::App* cmd = app.add_subcommand(
      "deform",
      "Apply a control-mesh state to a bound surface; writes the deformed surface (.vtp)");
  cmd->add_option("DATASET", a->dataset, "dataset (.json)")->required()->check(CLI::ExistingFile);
  cmd->add_option("BINDING", a->binding, "binding (.vtp from tetskin bind)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--positions", a->positions,
                  "deformed control nodes: .node (all dataset nodes or the bound level's) or .vtu")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "deformed surface (.vtp)")
      ->required()
      ->check(fileEnding(".vtp"));
  cmd->callback([a] { run(*a); });
}

}  // namespace tetskin::cli
