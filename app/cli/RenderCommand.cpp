// SPDX-License-Identifier: AGPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "AnimatedScene.h"
#include "Commands.h"
#include "MaterialOptions.h"
#include "OptionChecks.h"
#include "RunFilms.h"
#include "RunOptions.h"
#include "ScenarioOptions.h"
#include "SceneFlags.h"
#include "SurfaceInput.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/session/RunSpecJson.h"
#include "tetskin/session/SceneFile.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::cli {
namespace {

// The --help heading of the fur options.
constexpr const char* kFurGroup = "Fur (fur paths; default: the dataset config's fur section)";

struct RenderArgs {
  std::filesystem::path dataset, surface, output, texture, run;
  std::string path = toString(SceneOptions{}.path), camera = toString(SceneOptions{}.camera),
              control = SceneOptions{}.control,
              size = toString(ImageSize{SceneOptions{}.width, SceneOptions{}.height});
  ScenarioArgs scenario;
  MaterialOverrides material;  // over the config's elasticity
  double timeStep = SimulationOptions{}.timeStep;
  int level = kFinestLevel, frames = 0;
  bool printRun = false;
  // Fur: overrides of the dataset config's `fur` section.
  std::optional<int> furShells, furMinShells, furTextureSize;
  std::optional<double> furLength, furDensity, furDrag, furVelvet, furRepeats;
  std::optional<std::uint32_t> furSeed;
  std::optional<std::string> furLighting;
  std::optional<bool> furFins, furAdaptive;
};

FurParameters furParameters(const RenderArgs& a, const DatasetConfig& config) {
  FurParameters f = config.fur;
  if (a.furShells) f.shells = *a.furShells;
  if (a.furMinShells) f.minShells = *a.furMinShells;
  if (a.furTextureSize) f.textureSize = *a.furTextureSize;
  if (a.furLength) f.length = *a.furLength;
  if (a.furDensity) f.density = *a.furDensity;
  if (a.furDrag) f.drag = *a.furDrag;
  if (a.furVelvet) f.velvet = *a.furVelvet;
  if (a.furRepeats) f.textureRepeats = *a.furRepeats;
  if (a.furSeed) f.seed = *a.furSeed;
  if (a.furLighting) f.lighting = fromName<FurLighting>(*a.furLighting);
  if (a.furFins) f.fins = *a.furFins;
  if (a.furAdaptive) f.adaptiveShells = *a.furAdaptive;
  // The config's ranges, named by the option that sets each parameter.
  if (const auto problem = furParameterProblem(f)) {
    std::string option = problem->key;
    for (const NumberOption* o :
         {&fur_option::kShells, &fur_option::kMinShells, &fur_option::kLength,
          &fur_option::kDensity, &fur_option::kTextureSize, &fur_option::kTextureRepeats,
          &fur_option::kDrag, &fur_option::kVelvet})
      if (option == o->key) option = o->flag;
    throw Error(option + ": " + problem->what);
  }
  return f;
}

void run(const RenderArgs& a, const CLI::App& cmd) {
  SceneOptions o;
  const ImageSize size = checkedImageSize(a.size);
  o.width = size.width;
  o.height = size.height;
  o.path = fromName<RenderPath>(a.path);
  o.camera = fromName<CameraPreset>(a.camera);
  o.level = a.level;
  o.control = a.control;
  o.texture = a.texture;
  o.run.names = OptionNames::Flags;
  o.run.datasetName = a.dataset.string();
  o.run.settings.timeStep = a.timeStep;
  o.run.material = a.material;
  fromName<ControlMeshStyle>(o.control);  // reject typos before any work
  if (a.printRun && !a.run.empty())
    throw Error(
        "--print-run: prints the run --frames simulates (--run draws a recorded one as it was)");
  requireOutputOrPrintRun(a.output, a.printRun);
  if (const auto option = givenOptionOf(cmd, kFurGroup); option && !hasFur(o.path))
    throw Error(*option + ": applies to the fur paths (fur-cpu, fur-gpu), not to " + a.path);
  if (!a.run.empty() && a.frames > 0)
    throw Error("--frames: simulates a new run; --run draws the recorded one: give one of them");
  const bool film = lowerExtension(a.output) == ".ogv";
  if (film && a.run.empty() && a.frames == 0 && !a.printRun)
    throw Error("-o " + a.output.string() +
                ": a movie is filmed of a run: give --frames N (simulated now) or --run RUN.pvd "
                "(recorded)");
  std::optional<std::string> simulationOption = givenScenarioOption(cmd);
  if (!simulationOption) simulationOption = givenOptionOf(cmd, kMaterialGroup);
  if (!simulationOption) simulationOption = givenName(cmd, simulation_option::kTimeStep);
  if (simulationOption && a.frames == 0 && !a.printRun)
    throw Error(*simulationOption + ": applies to simulated frames; give --frames N" +
                (a.run.empty() ? "" : " (--run draws a recorded run as it was simulated)"));
  const bool levelGiven = cmd.count(kLevelOption.flag) > 0;
  // A scene brings its placed bodies (their union for several), their
  // skins bound, its obstacles and its run; a dataset its own.
  std::optional<SceneRun> sceneRun;
  if (isSceneFile(a.dataset)) {
    if (simulationOption)
      throw Error(*simulationOption + ": " + a.dataset.string() +
                  " is a scene, whose run is its own: set it in the scene");
    sceneRun = loadSceneWithFlags(
        a.dataset, levelGiven ? std::optional<int>(a.level) : std::nullopt, a.surface);
    if (!sceneRun->surface)
      throw Error(a.dataset.string() + ": its body has no surface to draw; give --surface");
    o.run = sceneRun->request;
    o.run.names = OptionNames::Flags;
  }
  const Dataset dataset = sceneRun ? sceneRun->dataset : loadDataset(a.dataset);
  // (An option out of range fails now, before any drawing.)
  o.run.material.over(dataset.config.elasticity, OptionNames::Flags);
  o.fur = furParameters(a, dataset.config);
  o.up = sceneRun && sceneRun->request.up ? *sceneRun->request.up
                                          : upAxisOf(a.scenario, dataset.config);
  if (hasFur(o.path) && o.texture.empty() && o.fur.colorTexture)
    o.texture = dataset.config.resolve(*o.fur.colorTexture);
  const std::optional<RecordedRun> recorded =
      a.run.empty() ? std::nullopt : std::optional<RecordedRun>(a.run);
  SurfaceInput input;
  if (sceneRun) {
    requireNotAnInput(a.output, {o.texture, sceneRun->surface->path, a.dataset});
    input = {sceneRun->surface->path, sceneRun->surface->surface, sceneRun->surface->binding};
  } else {
    // The surface: --surface; else a recorded run's own (its first surface
    // frame, a binding taken at its rest shape), else the dataset's.
    std::filesystem::path surfacePath = a.surface;
    if (surfacePath.empty() && recorded && recorded->surfaceFile())
      surfacePath = *recorded->surfaceFile();
    if (surfacePath.empty()) {
      if (!dataset.config.surface)
        throw Error(a.dataset.string(), 0, "names no default surface; give --surface");
      surfacePath = dataset.config.resolve(*dataset.config.surface);
    }
    requireNotAnInput(a.output, {o.texture, surfacePath, a.dataset});
    // A binding from `tetskin bind` is drawn as it is (method, offset, level).
    input = readSurfaceInput(surfacePath, dataset.mesh);
  }
  const int level = recorded ? runLevel(*recorded, input, dataset, a.level, levelGiven)
                             : commandLevel(input, dataset.mesh, a.level, levelGiven);
  o.level = level;
  const SurfaceMesh& surface = input.surface;
  const LevelRange& range = dataset.mesh.levels[static_cast<std::size_t>(level)];
  if (!sceneRun) fillScenario(cmd, a.scenario, range.nodeCount, o.run);
  if (a.printRun) {
    RunRequest request = o.run;
    request.level = level;
    std::printf("%s\n", runSpecJson(resolveRun(request, dataset.mesh, dataset.config)).c_str());
    return;
  }
  AnimatedScene scene(dataset, input, o);
  if (recorded) {
    const std::string restName =
        sceneRun ? "the scene " + a.dataset.string()
                 : "level " + std::to_string(level) + " of " + a.dataset.string();
    const TetMesh rest = extractLevel(dataset.mesh, level);
    if (film)
      filmRun(scene, *recorded, a.output, restName, rest);
    else
      drawRun(scene, *recorded, a.output, restName, rest);
    const std::size_t frames = recorded->frameCount();
    std::printf("drew %zu frames of %s (t %g .. %g s), path %s, %lld triangles, level %d, %dx%d\n",
                frames, a.run.c_str(), recorded->time(0), recorded->time(frames - 1),
                toString(o.path), static_cast<long long>(surface.triangleCount()), level, o.width,
                o.height);
    std::printf("  renderer: %s\n", scene.view().glRenderer().c_str());
    if (film)
      std::printf("wrote %s (%zu frames at %d frames/s)\n", a.output.c_str(), frames,
                  movieRate(recorded->meanFrameSeconds()));
    else
      std::printf("wrote %s .. %s\n", frameImage(a.output, 0).c_str(),
                  frameImage(a.output, frames - 1).c_str());
    return;
  }
  FrameStats s;
  if (film) {
    s = filmSimulation(scene, a.frames, a.output);
  } else {
    s = scene.run(a.frames);
    scene.view().writePng(a.output);
  }
  if (a.frames > 0) {
    std::printf("%d frames, path %s, %lld triangles, level %d (%lld tetrahedra), %dx%d\n", a.frames,
                toString(o.path), static_cast<long long>(surface.triangleCount()), scene.level(),
                static_cast<long long>(scene.elementCount()), o.width, o.height);
    std::printf("  scenario %s, %g s per frame, material: %s\n", a.scenario.name.c_str(),
                scene.frameSeconds(), describe(scene.material()).c_str());
    if (scene.furShells() > 0) std::printf("  fur: %d shells drawn\n", scene.furShells());
    std::printf(
        "  %.1f frames/s; per frame: simulation %.2f ms, deformation %.2f ms, upload %.2f ms, draw "
        "%.2f ms\n",
        s.framesPerSecond(), 1e3 * s.simulation / a.frames, 1e3 * s.deformation / a.frames,
        1e3 * s.upload / a.frames, 1e3 * s.draw / a.frames);
  }
  std::printf("  renderer: %s\n", scene.view().glRenderer().c_str());
  if (film)
    std::printf("wrote %s (%d frames at %d frames/s)\n", a.output.c_str(), a.frames,
                movieRate(scene.frameSeconds()));
  else
    std::printf("wrote %s\n", a.output.c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Headless rendering of a dataset's bound surface to PNG (needs X: use xvfb-run -a)");
  addDatasetOrSceneArgument(*cmd, a->dataset,
                            "its bodies, skins, obstacles, floor and run (a recorded run of "
                            "the scene is drawn on it)");
  cmd->add_option("--surface", a->surface,
                  "surface (default: a recorded run's own, else the dataset's surface; a scene's "
                  "body's)")
      ->check(CLI::ExistingFile);
  // (Names checked in run(), whose error lists them: --path, --camera,
  // --control, --fur-lighting.)
  cmd->add_option(kRenderPathOption.flag, a->path, kRenderPathOption.fullHelp())
      ->capture_default_str();
  cmd->add_option("-o,--output", a->output,
                  "image (.png); with --run, the images OUT_00000.png, ... or one movie (.ogv); "
                  "required unless --print-run")
      ->check(fileEnding(std::vector<std::string>{".png", ".ogv"}));
  cmd->add_option("--texture", a->texture,
                  "colour texture (PNG) for a surface with texture coordinates; on fur paths it "
                  "colours the fur and its alpha 0 masks it (default there: the config's "
                  "fur.color_texture)")
      ->check(CLI::ExistingFile);
  // (The fur values' ranges are io furParameterProblem's, checked in run();
  // the checks here only keep CLI11's "Could not convert" from the user.)
  using namespace fur_option;
  cmd->add_option(kShells.flag, a->furShells, kShells.help)
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  cmd->add_option(kMinShells.flag, a->furMinShells, kMinShells.help)
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  addFlagOf(*cmd, kAdaptiveShells, a->furAdaptive, kAdaptiveShells.help, trueOrFalse())
      ->group(kFurGroup);
  cmd->add_option(kLength.flag, a->furLength, kLength.help)
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option(kDensity.flag, a->furDensity, kDensity.help)
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option(kTextureSize.flag, a->furTextureSize, kTextureSize.help)
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  addFlagOf(*cmd, kTextureRepeats, a->furRepeats, kTextureRepeats.help, finiteNumber())
      ->group(kFurGroup);
  cmd->add_option(kSeed.flag, a->furSeed, kSeed.help)
      ->check(wholeNumberIn(kSeed.range))
      ->group(kFurGroup);
  cmd->add_option(kDrag.flag, a->furDrag, kDrag.help)->check(finiteNumber())->group(kFurGroup);
  cmd->add_option(kLighting.flag, a->furLighting, kLighting.fullHelp())->group(kFurGroup);
  cmd->add_option(kVelvet.flag, a->furVelvet, kVelvet.help)
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option(kFins.flag, a->furFins, kFins.help)->check(trueOrFalse())->group(kFurGroup);
  cmd->add_option(kLevelOption.flag, a->level, kLevelOption.help)->check(anyWholeNumber());
  cmd->add_option("--size", a->size, "WIDTHxHEIGHT")->capture_default_str()->check(imageSize());
  cmd->add_option(kCameraOption.flag, a->camera, kCameraOption.fullHelp())->capture_default_str();
  cmd->add_option(kControlMeshOption.flag, a->control, kControlMeshOption.fullHelp())
      ->capture_default_str();
  cmd->add_option("--frames", a->frames,
                  "simulate and draw N frames, report frames/s and a breakdown")
      ->check(wholeNumber(0));
  cmd->add_option("--run", a->run,
                  "draw a recorded run (.pvd from simulate or the GUI's Record): each control "
                  "frame to its own image, OUT_00000.png, OUT_00001.png, ... on the frames' level")
      ->check(CLI::ExistingFile)
      ->check(fileEnding(".pvd"));
  addPrintRunFlag(*cmd, a->printRun);
  addScenarioOptions(*cmd, a->scenario);
  addTimeStepOption(*cmd, a->timeStep)
      ->description(
          "with --frames: time step in seconds, the time each frame stands for (a film's "
          "frames/s is its inverse)");
  addMaterialOptions(*cmd, a->material);
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
