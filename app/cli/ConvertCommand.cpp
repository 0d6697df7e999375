// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/binding/BoundaryFaces.h"
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

// The boundary of tetrahedra as a surface file.
void writeBoundary(const std::filesystem::path& output, const TetMesh& mesh,
                   const std::string& what) {
  const SurfaceMesh boundary = boundarySurface(mesh);
  writeSurface(output, boundary);
  std::printf("wrote %s (the boundary of %s: %lld vertices, %lld triangles)\n", output.c_str(),
              what.c_str(), static_cast<long long>(boundary.vertexCount()),
              static_cast<long long>(boundary.triangleCount()));
}

void convertDataset(const ConvertOptions& o) {
  const bool toSurface = isSurfaceFile(o.output);
  if (!toSurface && lowerExtension(o.output) != ".vtu")
    throw Error(o.output.string(), 0,
                "a dataset converts to .vtu (one level) or to a surface (.obj .ply .stl .vtp: "
                "the level's boundary)");
  const Dataset dataset = loadDataset(o.input);
  const int level = resolveLevel(dataset.mesh, o.level);
  if (toSurface) {
    writeBoundary(o.output, extractLevel(dataset.mesh, level), "level " + std::to_string(level));
    return;
  }
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

// A tetrahedral .vtu (a run's frame, a level from convert) to the surface
// of its boundary, where its points are.
void convertTetrahedra(const ConvertOptions& o) {
  if (!isSurfaceFile(o.output))
    throw Error(o.output.string(), 0,
                "tetrahedra (.vtu) convert to a surface (.obj .ply .stl .vtp: their boundary)");
  const TetMesh mesh = fromVtkUnstructuredGrid(readVtu(o.input), o.input.string());
  writeBoundary(o.output, mesh, std::to_string(mesh.elementCount()) + " tetrahedra");
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto o = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Convert a surface between .obj/.ply/.stl/.vtp, a dataset level to .vtu for ParaView or to "
      "its boundary surface, or tetrahedra (.vtu: a run's frame) to their boundary surface");
  cmd->add_option("IN", o->input, "input surface, dataset (.json/.node/.ele) or tetrahedra (.vtu)")
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
    } else if (lowerExtension(o->input) == ".vtu") {
      if (cmd->count("--level") > 0)
        throw Error("--level: applies to a dataset's conversion, not to tetrahedra's");
      convertTetrahedra(*o);
    } else {
      throw Error(o->input.string(), 0,
                  "is neither a surface (.obj .ply .stl .vtp), a dataset (.json, or a "
                  ".node/.ele pair) nor tetrahedra (.vtu): convert takes those");
    }
  });
}

}  // namespace tetskin::cli
