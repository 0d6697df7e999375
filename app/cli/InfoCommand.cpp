// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "Commands.h"
#include "tetskin/binding/BindingSummary.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/TetrahedraFile.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/meshing/SurfaceNesting.h"
#include "tetskin/meshing/SurfaceRepair.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PartitionedSurface.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

void printBox(const BoundingBox& box) {
  std::printf("  bounds     [%g, %g, %g] .. [%g, %g, %g], diagonal %g\n", box.min.x(), box.min.y(),
              box.min.z(), box.max.x(), box.max.y(), box.max.z(), box.diagonal());
}

// Whether the surface is closed, as build needs it, and what it encloses:
// its parts, the cavities among them and the volume, wound as build's repair
// winds them (SurfaceNesting.h); or what keeps it open. Build's first
// repairs are made first, as build makes them: duplicate vertices welded (a
// triangle soup, as STL-like OBJ files are, has only open edges before),
// degenerate and duplicate triangles removed, and T-junctions split.
void printClosure(const SurfaceMesh& input) {
  if (input.triangleCount() == 0) return;
  SurfaceMesh mesh = input;
  RepairReport report;
  const RepairTolerances tolerance = repairTolerances({}, boundingBox(mesh).diagonal());
  weldAndClean(mesh, tolerance, report);
  report.tJunctionsSplit = splitTJunctions(mesh, tolerance.tJunction);  // (0 on a closed one)
  // "build welds 8 duplicate vertices, removes 1 degenerate triangle and
  // splits 26 T-junctions"
  std::vector<std::string> repairs;
  auto count = [](Index n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  if (report.weldedVertices > 0)
    repairs.push_back("welds " +
                      count(report.weldedVertices, "duplicate vertex", "duplicate vertices"));
  const Index degenerate = report.degenerateTriangles, duplicate = report.duplicateTriangles;
  if (degenerate > 0 || duplicate > 0)
    repairs.push_back(
        "removes " +
        (degenerate > 0 ? count(degenerate, "degenerate triangle", "degenerate triangles") : "") +
        (degenerate > 0 && duplicate > 0 ? " and " : "") +
        (duplicate > 0 ? count(duplicate, "duplicate triangle", "duplicate triangles") : ""));
  if (report.tJunctionsSplit > 0)
    repairs.push_back("splits " + count(report.tJunctionsSplit, "T-junction", "T-junctions"));
  std::string repaired;
  for (std::size_t i = 0; i < repairs.size(); ++i)
    repaired += (i == 0 ? "build " : i + 1 == repairs.size() ? " and " : ", ") + repairs[i];
  if (const auto holes = boundaryLoops(mesh).size(); holes > 0) {
    std::printf("  closed     no: %zu chain%s of open edges", holes, holes == 1 ? "" : "s");
    if (!repaired.empty()) std::printf(" once %s", repaired.c_str());
    std::printf(" (build removes triangles on open edges and refuses real holes)\n");
    return;
  }
  const Index nonManifold = nonManifoldEdgeCount(mesh);
  SurfaceMesh wound = mesh;
  const OrientationResult orientation = orientConsistently(wound);
  std::printf("  closed     yes");
  if (!repaired.empty()) std::printf(" once %s", repaired.c_str());
  if (!orientation.orientable) {
    std::printf(", but not orientable\n");
    return;
  }
  const std::size_t parts = surfaceParts(wound).triangles.size();
  std::printf(": %zu part%s", parts, parts == 1 ? "" : "s");
  if (orientation.cavities > 0)
    std::printf(", %lld bounding a cavit%s", static_cast<long long>(orientation.cavities),
                orientation.cavities == 1 ? "y" : "ies");
  if (nonManifold > 0)
    std::printf(", %lld edge%s shared by more than two triangles",
                static_cast<long long>(nonManifold), nonManifold == 1 ? "" : "s");
  // (Where triangles intersect, the volume counts overlapping parts twice.)
  if (!findSelfIntersections(mesh, 1).empty())
    std::printf(
        ", triangles intersecting (build collapses them); volume %g counting overlaps "
        "twice\n",
        enclosedVolume(wound));
  else
    std::printf("; volume %g\n", enclosedVolume(wound));
}

void printSurface(const std::filesystem::path& path, const SurfaceMesh& mesh, const char* kind) {
  std::printf("%s: %s\n", path.c_str(), kind);
  std::printf("  vertices   %lld\n  triangles  %lld\n", static_cast<long long>(mesh.vertexCount()),
              static_cast<long long>(mesh.triangleCount()));
  std::printf("  normals    %s\n  texcoords  %s\n", mesh.hasNormals() ? "yes" : "no",
              mesh.hasTexcoords() ? "yes" : "no");
  std::printf("  area       %g\n", surfaceArea(mesh));
  printClosure(mesh);
  printBox(boundingBox(mesh));
  if (const NormalGaps gaps = normalGaps(mesh); !gaps.empty())
    std::printf("  warning: %s\n", describe(gaps).c_str());
}

// What a binding's own dataset says of it, as a warning (info describes a
// file, it refuses none): the dataset missing or unreadable, ids that do not
// fit it, or a surface far from its level (misfitWarning, as bind warned).
std::string datasetWarning(const std::filesystem::path& path, const BoundSurface& bound,
                           const BindingSummary& summary) {
  const std::string& dataset = bound.dataset;
  if (dataset.empty()) return {};
  if (!std::filesystem::exists(dataset))
    return "its dataset " + dataset + " is not there (moved without the binding?)";
  try {
    const Dataset loaded = loadDataset(dataset);
    checkBindingFits(bound, loaded.mesh, path.string());
    return misfitWarning(summary, loaded.mesh, bound.binding.level);
  } catch (const Error& e) {
    return e.what();
  }
}

// A .vtp from `tetskin bind`: the surface, what it is bound to, and the
// binding's quality summary as `bind` printed it. A deformed one (from
// deform, simulate or the GUI) is described as it is in the file, moved.
void printBinding(const std::filesystem::path& path, vtkPolyData* data) {
  const BoundSurface bound = bindingFromFile(data, path);
  printSurface(
      path, shownSurface(bound),
      bound.deformed ? "binding, deformed (its rest shape: points - Displacement)" : "binding");
  std::printf("  dataset    %s\n", bound.dataset.c_str());
  const BindingSummary summary =
      summarizeBinding(bound.binding, boundingBox(bound.surface).diagonal());
  std::fputs(formatSummary(summary, bound.binding).c_str(), stdout);
  if (const std::string warning = datasetWarning(path, bound, summary); !warning.empty())
    std::printf("  warning: %s\n", warning.c_str());
}

// Element volumes of a tetrahedral mesh: their sum, the smallest, and the
// elements that are not positive (inverted or degenerate).
struct Volumes {
  double total = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  Index nonPositive = 0;
  Index firstNonPositive = -1;
};

Volumes volumes(const TetMesh& mesh) {
  Volumes result;
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    const double v = elementVolume(mesh, e);
    result.total += v;
    result.smallest = std::min(result.smallest, v);
    if (!(v > 0) && result.nonPositive++ == 0) result.firstNonPositive = e;
  }
  return result;
}

void printDataset(const std::filesystem::path& path) {
  const Dataset dataset = loadDataset(path);
  std::printf("%s: dataset, %d level(s), %lld nodes, %lld elements\n", path.c_str(),
              dataset.mesh.levelCount(), static_cast<long long>(dataset.mesh.nodes.rows()),
              static_cast<long long>(dataset.mesh.elements.rows()));
  printBox(boundingBox(dataset.mesh.nodes));
  std::printf("  up         %s\n", toString(dataset.config.up));
  std::printf("  elasticity %s\n", describe(dataset.config.elasticity).c_str());
  std::printf("  %-5s %8s %9s %12s %12s %8s  %s\n", "level", "nodes", "elements", "volume",
              "min volume", "min dih", "source");
  std::string warnings, levelNotes;  // (each level's wrap and fidelity)
  for (int k = 0; k < dataset.mesh.levelCount(); ++k) {
    const TetMesh level = extractLevel(dataset.mesh, k);
    const Volumes v = volumes(level);
    if (v.nonPositive > 0)
      warnings += "  warning: level " + std::to_string(k) + " has " +
                  std::to_string(v.nonPositive) +
                  " inverted or degenerate element(s) (first: element " +
                  std::to_string(v.firstNonPositive) +
                  "); simulate refuses it (and multigrid on finer levels)\n";
    // Measured, not the config's statistics: a dataset converted or edited
    // elsewhere may have none, or stale ones.
    const TetQuality quality = measureQuality(level);
    if (const std::string problem = sliverProblem(quality); !problem.empty())
      warnings += "  warning: level " + std::to_string(k) + " " + problem + "\n";
    const LevelSource& src = dataset.config.levels[static_cast<std::size_t>(k)].source;
    std::string how = src.mesher;
    if (const std::optional<MesherKind> mesher = parseName<MesherKind>(src.mesher))
      how += " " + meshingLabel(*mesher, src.quality, src.sizeBound);
    if (src.wrap) how += " (wrapped)";
    std::printf("  %-5d %8lld %9lld %12g %12g %8.2f  %s %s\n", k,
                static_cast<long long>(level.nodeCount()),
                static_cast<long long>(level.elementCount()), v.total, v.smallest,
                quality.minDihedralDeg, src.input.c_str(), how.c_str());
    if (src.wrap)
      levelNotes += "  level " + std::to_string(k) + " wrap: " + describe(*src.wrap) + "\n";
    if (const std::optional<LevelFidelity>& f =
            dataset.config.levels[static_cast<std::size_t>(k)].fidelity) {
      levelNotes += "  level " + std::to_string(k) + " against the input: " + describe(*f) + "\n";
      if (!f->faithful)
        warnings += "  warning: level " + std::to_string(k) +
                    " lies off its input beyond its fidelity bound (written with "
                    "--accept-unfaithful)\n";
    }
  }
  std::fputs(levelNotes.c_str(), stdout);
  std::fputs(warnings.c_str(), stdout);
}

// A .vtu (`convert` of a level, a frame of `simulate`): the tetrahedra, and
// each point and cell array with its range (of magnitudes for vectors).
void printTetMesh(const std::filesystem::path& path) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(path);
  const TetMesh mesh = fromVtkUnstructuredGrid(grid, path.string());
  std::printf("%s: tetrahedral mesh\n", path.c_str());
  std::printf("  nodes      %lld\n  elements   %lld\n", static_cast<long long>(mesh.nodeCount()),
              static_cast<long long>(mesh.elementCount()));
  const Volumes v = volumes(mesh);
  std::printf("  volume     %g (smallest element %g)\n", v.total, v.smallest);
  printBox(boundingBox(mesh.nodes));
  const auto printArrays = [](const char* kind, vtkFieldData* arrays) {
    for (int i = 0; i < arrays->GetNumberOfArrays(); ++i) {
      vtkDataArray* array = arrays->GetArray(i);
      if (!array) continue;  // (not numeric)
      const int components = array->GetNumberOfComponents();
      double range[2];
      array->GetRange(range, components == 1 ? 0 : -1);
      std::printf("  %-10s %s (%d component%s): %s %g .. %g\n", kind, array->GetName(), components,
                  components == 1 ? "" : "s", components == 1 ? "range" : "length", range[0],
                  range[1]);
      kind = "";
    }
  };
  printArrays("point data", grid->GetPointData());
  printArrays("cell data", grid->GetCellData());
  // A simulated frame's forces in all (the array ranges above give their
  // largest per node): what pushes the body, what holds it.
  std::string forces;
  for (const auto& [name, label] : {std::pair{arrays::kExternalForce, "external"},
                                    std::pair{arrays::kReactionForce, "reaction"}}) {
    const std::optional<Points3> perNode = fromVtkVectors(grid->GetPointData()->GetArray(name));
    if (!perNode) continue;
    forces += std::string(forces.empty() ? "" : ", ") + label + " " +
              commaSeparated(perNode->colwise().sum().transpose()) + " N";
  }
  if (!forces.empty()) std::printf("  forces     %s in all\n", forces.c_str());
}

// A Gmsh (.msh) or MEDIT (.mesh) volume mesh: its tetrahedra as `convert`
// takes them, and what it leaves out.
void printMeshFile(const std::filesystem::path& path) {
  const TetrahedraFile read = readTetrahedraFile(path);
  std::printf("%s: %s mesh\n", path.c_str(), read.format.c_str());
  std::printf("  nodes      %lld\n  elements   %lld tetrahedr%s",
              static_cast<long long>(read.mesh.nodeCount()),
              static_cast<long long>(read.mesh.elementCount()),
              read.mesh.elementCount() == 1 ? "on" : "a");
  if (read.skippedElements > 0)
    std::printf(" (%lld elements of lower dimension left out)",
                static_cast<long long>(read.skippedElements));
  std::printf("\n");
  const Volumes v = volumes(read.mesh);
  std::printf("  volume     %g (smallest element %g)\n", v.total, v.smallest);
  printBox(boundingBox(read.mesh.nodes));
}

// A .pvtp's pieces (it was described whole before).
void printPieces(const std::filesystem::path& path) {
  const std::vector<std::filesystem::path> pieces = pvtpPieceFiles(path);
  std::printf("  pieces     %zu (%s .. %s), read whole\n", pieces.size(),
              pieces.front().filename().c_str(), pieces.back().filename().c_str());
}

// Whether a series' file is there: for a .pvtp, every piece it names too.
bool seriesFilePresent(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) return false;
  if (lowerExtension(file) != ".pvtp") return true;
  try {
    for (const std::filesystem::path& piece : pvtpPieceFiles(file))
      if (!std::filesystem::is_regular_file(piece)) return false;
  } catch (const Error&) {
    return false;
  }
  return true;
}

// A .pvd (from simulate, the GUI's recorder or ParaView): its time steps and,
// per part, how many files it lists and whether they are all there.
void printSeries(const std::filesystem::path& path) {
  const PvdSeries series = PvdSeries::read(path);
  std::set<double> times;
  std::map<int, std::vector<std::string>> filesOfPart;
  for (const PvdSeries::Entry& e : series.entries()) {
    times.insert(e.time);
    filesOfPart[e.part].push_back(e.file);
  }
  std::printf("%s: time series, %zu time step%s", path.c_str(), times.size(),
              times.size() == 1 ? "" : "s");
  if (!times.empty()) std::printf(", t %g .. %g", *times.begin(), *times.rbegin());
  std::printf("\n");
  const std::filesystem::path folder = path.parent_path();
  for (const auto& [part, files] : filesOfPart) {
    std::size_t missing = 0;
    std::string firstMissing;
    for (const std::string& f : files)
      if (!seriesFilePresent(folder / f) && missing++ == 0) firstMissing = f;
    std::printf("  part %d     %zu file%s, %s .. %s", part, files.size(),
                files.size() == 1 ? "" : "s", files.front().c_str(), files.back().c_str());
    if (missing == 0)
      std::printf(", all present\n");
    else
      std::printf(", %zu missing (first: %s)\n", missing, firstMissing.c_str());
  }
  // The level of the control-mesh frames, which render --run, deform and
  // the GUI draw the run on, the run's floor, which they draw, and how many
  // nodes it held or drove (where the first frame can be read and says).
  if (const auto control = filesOfPart.find(0); control != filesOfPart.end()) {
    SimulationFrameFacts facts;
    try {
      facts = simulationFrameFacts(folder / control->second.front());
    } catch (const Error&) {  // (a missing or broken frame is named above or when read)
    }
    if (facts.level) std::printf("  level      %d (of the control-mesh frames)\n", *facts.level);
    if (const std::optional<FloorPlane>& floor = facts.conditions.floor)
      std::printf("  floor      %s = %s\n", toString(floor->up),
                  formatNumber(floor->height).c_str());
    if (const std::size_t held = facts.conditions.prescribedNodes.size(); held > 0)
      std::printf("  prescribed %zu node%s (held still or driven)\n", held, held == 1 ? "" : "s");
  }
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto files = std::make_shared<std::vector<std::filesystem::path>>();
  CLI::App* cmd = app.add_subcommand(
      "info",
      "Print a summary of surfaces (.obj/.ply/.stl/.vtp, .pvtp in pieces read whole), bindings "
      "(.vtp from bind: what they are "
      "bound to and their quality), tetrahedral meshes (.vtu from convert or simulate: arrays "
      "and their ranges; Gmsh .msh, MEDIT .mesh), time series (.pvd: steps, files, any missing) "
      "and datasets "
      "(.json/.node/.ele)");
  cmd->add_option("FILE", *files, "files to describe")->required()->check(CLI::ExistingFile);
  cmd->callback([files] {
    for (const auto& path : *files) {
      const std::string extension = lowerExtension(path);
      if (extension == ".vtp" || extension == ".pvtp") {
        const vtkSmartPointer<vtkPolyData> data = readVtp(path);  // (a .pvtp whole)
        if (isBinding(data))
          printBinding(path, data);
        else  // (what readSurface makes of a .vtp, without reading it again)
          printSurface(path, fromVtkPolyData(data, path.string()), "surface");
        if (extension == ".pvtp") printPieces(path);
      } else if (isSurfaceFile(path)) {
        printSurface(path, readSurface(path), "surface");
      } else if (extension == ".vtu") {
        printTetMesh(path);
      } else if (extension == ".pvd") {
        printSeries(path);
      } else if (extension == ".msh" || extension == ".mesh") {
        printMeshFile(path);
      } else if (isDatasetFile(path)) {
        printDataset(path);
      } else {
        throw Error(
            path.string(), 0,
            "info reads surfaces (.obj .ply .stl .vtp .pvtp), tetrahedral meshes (.vtu, Gmsh .msh, "
            "MEDIT "
            ".mesh), time "
            "series "
            "(.pvd) and datasets (.json .node .ele), not " +
                (extension.empty() ? "files without an extension" : "'" + extension + "' files"));
      }
    }
  });
}

}  // namespace tetskin::cli
