// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct ConvertOptions {
  std::filesystem::path input;
  std::filesystem::path output;
  int level = -1;
};

void convertDataset(const ConvertOptions& o) {
  if (lowerExtension(o.output) != ".vtu")
    throw Error(o.output.string(), 0, "a dataset converts to .vtu (one level)");
  const Dataset dataset = loadDataset(o.input);
  const int level = resolveLevel(dataset.mesh, o.level);
  vtkSmartPointer<vtkUnstructuredGrid> grid =
      toVtkUnstructuredGrid(extractLevel(dataset.mesh, level));
  auto levelArray = vtkSmartPointer<vtkIntArray>::New();
  levelArray->SetName("Level");
  levelArray->SetNumberOfValues(grid->GetNumberOfCells());
  levelArray->FillValue(level);
  grid->GetCellData()->AddArray(levelArray);
  writeVtu(o.output, grid);
  std::printf("wrote %s (level %d: %lld nodes, %lld tetrahedra)\n", o.output.c_str(), level,
              static_cast<long long>(grid->GetNumberOfPoints()),
              static_cast<long long>(grid->GetNumberOfCells()));
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto o = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Convert a surface between .obj/.ply/.stl/.vtp, or a dataset level to .vtu for ParaView");
  cmd->add_option("IN", o->input, "input surface or dataset (.json/.node/.ele)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("OUT", o->output, "output file")->required();
  cmd->add_option("--level", o->level, kLevelHelp)->check(anyWholeNumber());
  cmd->callback([o, cmd] {
    requireNotAnInput(o->output, {o->input});
    if (isSurfaceFile(o->input)) {
      if (cmd->count("--level") > 0)
        throw Error("--level: applies to a dataset's conversion, not to a surface's");
      const SurfaceMesh mesh = readSurface(o->input);
      writeSurface(o->output, mesh);
      std::printf("wrote %s (%lld vertices, %lld triangles)\n", o->output.c_str(),
                  static_cast<long long>(mesh.vertexCount()),
                  static_cast<long long>(mesh.triangleCount()));
    } else if (isDatasetFile(o->input)) {
      convertDataset(*o);
    } else {
      // (e.g. a frame .vtu of a run, whose output check would otherwise
      // blame OUT for an input that convert does not take)
      throw Error(o->input.string(), 0,
                  "is neither a surface (.obj .ply .stl .vtp) nor a dataset (.json, or a "
                  ".node/.ele pair): convert takes those");
    }
  });
}

}  // namespace tetskin::cli
