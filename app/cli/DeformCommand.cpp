// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/session/SkinFields.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct DeformArgs {
  std::filesystem::path dataset, binding, positions, output;
  int pieces = static_cast<int>(kPiecesOption.defaultValue);
};

Points3 readPositions(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  if (extension == ".node") return readNode(path).points;
  if (extension == ".vtu") return fromVtkUnstructuredGrid(readVtu(path), path.string()).nodes;
  throw Error(path.string(), 0,
              "positions must be a .node file, a .vtu with deformed points or a recorded run "
              "(.pvd)");
}

// `--positions RUN.pvd`: each control frame of a recorded run applied to the
// binding, written as the series OUT.pvd of the deformed surface (part 1,
// as simulate --surface writes it). Every frame is read once before any is
// written, so a frame of another body or level leaves no output.
void deformRun(const DeformArgs& a, const Dataset& dataset, BoundSurface bound) {
  const RecordedRun recorded(a.positions);
  const int level = bound.binding.level;
  const TetMesh rest = extractLevel(dataset.mesh, level);
  const std::string restName = "level " + std::to_string(level) + " of " + a.dataset.string() +
                               " (the level " + a.binding.string() + " is bound to)";
  const std::size_t frames = recorded.frameCount();
  const std::filesystem::path written = RunRecorder::framesDirectory(a.output);
  for (std::size_t i = 0; i < frames; ++i) {
    // (The series' writer clears its folder of earlier frames first.)
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::path(recorded.file(i)).parent_path();
    if (std::filesystem::equivalent(folder.empty() ? "." : folder, written, error))
      throw Error(recorded.file(i), 0,
                  "is in the folder the series -o " + a.output.string() +
                      " writes its frames to: write it to another name");
    recorded.read(i, rest, restName);
  }
  requireWritableLocation(a.output);
  SurfaceDeformer deformer(bound.surface, bound.binding, dataset.mesh.nodes);
  bound.dataset = a.dataset.generic_string();
  RunRecorder series(a.output, {}, a.pieces);
  Points3 positions, normals;
  for (std::size_t i = 0; i < frames; ++i) {
    const FrameState state = recorded.read(i, rest, restName);
    deformer.deform(datasetPositions(dataset.mesh, level, state.positions, recorded.file(i)),
                    positions, normals);
    // With the frame's stress and strain on the skin, as simulate writes it.
    bound.deformed = DeformedState{
        positions, normals,
        skinFields(rest, dataset.mesh.levels[static_cast<std::size_t>(level)].firstNode,
                   bound.binding, state.vonMisesStress, state.equivalentStrain)};
    series.addSurfaceFrame(recorded.time(i), bound);
  }
  std::printf("wrote %s (%zu frames of %lld vertices deformed by %s, t %g .. %g s)\n",
              a.output.c_str(), frames, static_cast<long long>(positions.rows()),
              a.positions.c_str(), recorded.time(0), recorded.time(frames - 1));
}

void run(const DeformArgs& a) {
  // The output's format follows the positions', checked before any work.
  const bool recordedRun = lowerExtension(a.positions) == ".pvd";
  if (recordedRun && lowerExtension(a.output) != ".pvd")
    throw Error("-o " + a.output.string() +
                ": the surface of a recorded run (--positions RUN.pvd) is a series: name a .pvd");
  const std::string outputExtension = lowerExtension(a.output);
  if (!recordedRun && outputExtension != ".vtp" && outputExtension != ".pvtp")
    throw Error("-o " + a.output.string() +
                ": a deformed surface is a .vtp, or a .pvtp in pieces (a .pvd series is written "
                "for a recorded run, --positions RUN.pvd)");
  if (!recordedRun && a.pieces > 1 && outputExtension != ".pvtp")
    throw Error("-o " + a.output.string() + ": a surface in " + std::to_string(a.pieces) +
                " pieces is written as a .pvtp");
  requireNotAnInput(a.output, {a.dataset, a.binding, a.positions});
  const Dataset dataset = loadDataset(a.dataset);
  BoundSurface bound = readBinding(a.binding, dataset.mesh);
  if (recordedRun) return deformRun(a, dataset, std::move(bound));
  const int level = bound.binding.level;
  const Points3 control =
      datasetPositions(dataset.mesh, level, readPositions(a.positions), a.positions.string());
  SurfaceDeformer deformer(bound.surface, bound.binding, dataset.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(control, positions, normals);
  bound.deformed = DeformedState{positions, normals};
  bound.dataset = a.dataset.generic_string();  // the one its ids were checked against
  if (outputExtension == ".pvtp")
    writeBinding(a.output, bound, restPieces(bound, a.pieces));
  else
    writeBinding(a.output, bound);
  std::printf("wrote %s (%lld vertices deformed by %s)\n", a.output.c_str(),
              static_cast<long long>(positions.rows()), a.positions.c_str());
}

}  // namespace

void addDeformCommand(CLI::App& app) {
  auto a = std::make_shared<DeformArgs>();
  CLI::App* cmd = app.add_subcommand(
      "deform",
      "Apply a control-mesh state to a bound surface; writes the deformed surface (.vtp, "
      ".pvtp)");
  cmd->add_option("DATASET", a->dataset, kDatasetHelp)->required()->check(CLI::ExistingFile);
  cmd->add_option("BINDING", a->binding, "binding (.vtp from tetskin bind)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--positions", a->positions,
                  "deformed control nodes: .node (all dataset nodes or the bound level's), .vtu, "
                  "or a recorded run (.pvd: every control frame, written as a series)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output,
                  "deformed surface (.vtp, or .pvtp in pieces); for a recorded run, its series "
                  "(.pvd)")
      ->required();
  addNumberOption(*cmd, kPiecesOption, a->pieces);
  addCompressOption(*cmd);
  cmd->callback([a] { run(*a); });
}

}  // namespace tetskin::cli
