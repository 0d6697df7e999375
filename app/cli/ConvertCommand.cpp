// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/MeditFormat.h"
#include "tetskin/io/TetrahedraFile.h"
#include "tetskin/meshing/MeshQuality.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct ConvertOptions {
  std::vector<std::filesystem::path> files;  // the inputs, then the output
  std::filesystem::path input;               // the one input, when there is one
  std::filesystem::path output;
  int level = kFinestLevel;
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
  const std::string extension = lowerExtension(o.output);
  if (!toSurface && extension != ".vtu" && extension != ".mesh")
    throw Error(o.output.string(), 0,
                "a dataset converts to .vtu (one level, for ParaView), to MEDIT .mesh (one "
                "level: its nodes, boundary triangles and tetrahedra) or to a surface (.obj .ply "
                ".stl .vtp: the level's boundary)");
  const Dataset dataset = loadDataset(o.input);
  const int level = resolveLevel(dataset.mesh, o.level);
  if (toSurface) {
    writeBoundary(o.output, extractLevel(dataset.mesh, level), "level " + std::to_string(level));
    return;
  }
  if (extension == ".mesh") {
    const TetMesh tets = extractLevel(dataset.mesh, level);
    MeditMesh medit{tets.nodes, boundaryFaces(tets).faces, tets.elements, 0};
    writeMedit(o.output, medit);
    std::printf("wrote %s (level %d: %lld nodes, %lld boundary triangles, %lld tetrahedra)\n",
                o.output.c_str(), level, static_cast<long long>(medit.vertices.rows()),
                static_cast<long long>(medit.triangles.rows()),
                static_cast<long long>(medit.tetrahedra.rows()));
    return;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid =
      toVtkUnstructuredGrid(extractLevel(dataset.mesh, level));
  auto levelArray = vtkSmartPointer<vtkIntArray>::New();
  levelArray->SetName(arrays::kLevel);
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

// Tetrahedral meshes made elsewhere (.vtu: ParaView, meshio, another
// mesher; Gmsh's .msh; TetGen's .node/.ele), one per level, as a dataset: coarsest first, each with
// its lower-dimensional cells left out, its unreferenced points dropped and
// its inverted elements turned.
void importDataset(const std::vector<std::filesystem::path>& inputs,
                   const std::filesystem::path& output) {
  const std::filesystem::path json = datasetConfigPath(output);
  const std::filesystem::path directory = std::filesystem::absolute(json).parent_path();
  struct Level {
    std::filesystem::path file;
    TetMesh mesh;
    Index skipped = 0, unreferenced = 0, flipped = 0;
    TetQuality quality;
  };
  std::vector<Level> levels;
  for (const std::filesystem::path& input : inputs) {
    Level level;
    level.file = input;
    // Each element named as its file names it: a .vtu's cell number, a
    // .msh's element tag, a TetGen .ele's element number.
    std::function<std::string(Index)> elementName;
    const std::string extension = lowerExtension(input);
    if (extension == ".vtu") {
      ImportedTetrahedra imported = tetrahedraOf(readVtu(input), input.string());
      level.mesh = std::move(imported.mesh);
      level.skipped = imported.skippedCells;
      elementName = [cells = std::move(imported.cells)](Index e) {
        return "cell " + std::to_string(cells[static_cast<std::size_t>(e)]);
      };
    } else if (isTetrahedraFile(input)) {
      TetrahedraFile imported = readTetrahedraFile(input);
      level.mesh = std::move(imported.mesh);
      level.skipped = imported.skippedElements;
      elementName = [file = std::move(imported)](Index e) { return file.elementName(e); };
    } else {
      throw Error(input.string(), 0,
                  "is not tetrahedra (.vtu, Gmsh .msh, MEDIT .mesh, or a TetGen .node/.ele "
                  "pair): a dataset is made of one tetrahedral mesh per level");
    }
    level.unreferenced = removeUnreferencedNodes(level.mesh);
    level.flipped = orientElementsPositively(level.mesh);
    for (Index e = 0; e < level.mesh.elementCount(); ++e)  // (a flat one stays flat)
      if (!(elementVolume(level.mesh, e) > 0))
        throw Error(input.string(), 0,
                    elementName(e) + ", a tetrahedron, has volume " +
                        formatNumber(elementVolume(level.mesh, e)) + " (degenerate)");
    level.quality = measureQuality(level.mesh);
    levels.push_back(std::move(level));
  }
  std::stable_sort(levels.begin(), levels.end(), [](const Level& a, const Level& b) {
    return a.mesh.elementCount() < b.mesh.elementCount();
  });
  const BoundingBox finest = boundingBox(levels.back().mesh.nodes);
  for (const Level& level : levels)
    if (const std::string mismatch = levelOfDetailMismatch(finest, boundingBox(level.mesh.nodes),
                                                           levels.back().file.string());
        !mismatch.empty())
      throw Error(level.file.string(), 0, mismatch);
  Dataset dataset;
  nlohmann::json provenance = nlohmann::json::array();
  for (const Level& level : levels) {
    appendLevel(dataset.mesh, level.mesh);
    LevelConfig config;
    config.source.input =
        std::filesystem::relative(std::filesystem::absolute(level.file), directory)
            .generic_string();
    config.source.mesher = "imported";
    config.statistics = level.quality.asMap();
    dataset.config.levels.push_back(config);
    provenance.push_back({{"file", config.source.input},
                          {"skipped_cells", level.skipped},
                          {"unreferenced_nodes_removed", level.unreferenced},
                          {"flipped_elements", level.flipped}});
  }
  dataset.config.provenance = {{"tool", "tetskin convert"}, {"inputs", provenance}};
  saveDataset(json, dataset);
  std::printf("%-5s %9s %8s %8s %8s  %s\n", "level", "elements", "nodes", "min dih", "max r/e",
              "input");
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const Level& level = levels[k];
    std::printf("%-5zu %9lld %8lld %8.2f %8.3f  %s", k,
                static_cast<long long>(level.mesh.elementCount()),
                static_cast<long long>(level.mesh.nodeCount()), level.quality.minDihedralDeg,
                level.quality.maxRadiusEdge, level.file.c_str());
    if (level.skipped > 0)
      std::printf(" (%lld lower cells left out)", static_cast<long long>(level.skipped));
    if (level.unreferenced > 0)
      std::printf(" (%lld unused points dropped)", static_cast<long long>(level.unreferenced));
    if (level.flipped > 0)
      std::printf(" (%lld inverted elements turned)", static_cast<long long>(level.flipped));
    std::printf("\n");
  }
  std::printf("wrote %s (+ .node, .ele)\n", json.c_str());
  for (std::size_t k = 0; k < levels.size(); ++k)
    if (const std::string problem = sliverProblem(levels[k].quality); !problem.empty())
      std::fprintf(stderr, "warning: level %zu (%s) %s\n", k, levels[k].file.c_str(),
                   problem.c_str());
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto o = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert",
      "Convert a surface between .obj/.ply/.stl/.vtp, a dataset level (a Gmsh .msh or MEDIT "
      ".mesh too) to .vtu for ParaView, to MEDIT .mesh or to its boundary surface, tetrahedra "
      "(.vtu: a run's frame) to their boundary surface, or tetrahedral meshes made elsewhere "
      "(.vtu, Gmsh .msh, MEDIT .mesh, TetGen .node/.ele; one per level) to a dataset (.json)");
  cmd->add_option(
         "FILES", o->files,
         "IN OUT: the input (a surface, a dataset .json/.node/.ele/.msh/.mesh, or tetrahedra "
         ".vtu) and the output file; or IN IN ... OUT.json: tetrahedra (.vtu, Gmsh .msh, MEDIT "
         ".mesh, TetGen .node/.ele), one per level, to a dataset")
      ->required()
      ->expected(-2);
  cmd->add_option(kLevelOption.flag, o->level, kLevelOption.help)->check(anyWholeNumber());
  addCompressOption(*cmd);
  cmd->callback([o, cmd] {
    o->output = o->files.back();
    const std::vector<std::filesystem::path> inputs(o->files.begin(), o->files.end() - 1);
    for (const std::filesystem::path& input : inputs) {
      std::error_code error;
      if (!std::filesystem::is_regular_file(input, error))
        throw Error(input.string(), 0, "is not a file that exists");
      requireNotAnInput(o->output, {input});
    }
    if (lowerExtension(o->output) == ".json") {
      if (cmd->count(kLevelOption.flag) > 0)
        throw Error(std::string(kLevelOption.flag) +
                    ": applies to a dataset's conversion, not to making one");
      importDataset(inputs, o->output);
      return;
    }
    if (inputs.size() > 1)
      throw Error(o->output.string(), 0,
                  "several inputs convert only to a dataset (.json: tetrahedral meshes, one per "
                  "level)");
    o->input = inputs.front();
    if (isSurfaceFile(o->input)) {
      if (cmd->count(kLevelOption.flag) > 0)
        throw Error(std::string(kLevelOption.flag) +
                    ": applies to a dataset's conversion, not to a surface's");
      const SurfaceMesh mesh = readSurface(o->input);
      writeSurface(o->output, mesh);
      std::printf("wrote %s (%lld vertices, %lld triangles)\n", o->output.c_str(),
                  static_cast<long long>(mesh.vertexCount()),
                  static_cast<long long>(mesh.triangleCount()));
    } else if (isDatasetFile(o->input)) {
      convertDataset(*o);
    } else if (lowerExtension(o->input) == ".vtu") {
      if (cmd->count(kLevelOption.flag) > 0)
        throw Error(std::string(kLevelOption.flag) +
                    ": applies to a dataset's conversion, not to tetrahedra's");
      convertTetrahedra(*o);
    } else {
      throw Error(o->input.string(), 0,
                  "is neither a surface (.obj .ply .stl .vtp), a dataset (.json, or a "
                  ".node/.ele pair, a Gmsh .msh, a MEDIT .mesh) nor tetrahedra (.vtu): convert "
                  "takes those");
    }
  });
}

}  // namespace tetskin::cli
