// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkImageData.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "AnimatedScene.h"
#include "Commands.h"
#include "OptionChecks.h"
#include "ScenarioOptions.h"
#include "SurfaceInput.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::cli {
namespace {

// The --help heading of the fur options.
constexpr const char* kFurGroup = "Fur (fur paths; default: the dataset config's fur section)";

struct RenderArgs {
  std::filesystem::path dataset, surface, output, texture, run;
  std::string path = "cpu", camera = "iso", control = "none", size = "800x600";
  ScenarioArgs scenario;
  int level = -1, frames = 0;
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
  if (a.furLighting) f.lighting = parseFurLighting(*a.furLighting);
  if (a.furFins) f.fins = *a.furFins;
  if (a.furAdaptive) f.adaptiveShells = *a.furAdaptive;
  // The config's ranges, named by the option that sets each parameter.
  if (const auto problem = furParameterProblem(f)) {
    std::string option = problem->key == "texture_repeats" ? "repeats" : problem->key;
    std::replace(option.begin(), option.end(), '_', '-');
    throw Error("--fur-" + option + ": " + problem->what);
  }
  return f;
}

// The level a run's frames are of (their Level array; where the first frame
// has none, --level's), which --level and a binding must not contradict.
int runLevel(const RecordedRun& recorded, const SurfaceInput& input, const Dataset& dataset,
             int levelOption, bool levelGiven) {
  if (!recorded.level()) return commandLevel(input, dataset.mesh, levelOption, levelGiven);
  const int level = *recorded.level();
  if (level < 0 || level >= static_cast<int>(dataset.mesh.levels.size()))
    throw Error(recorded.file(0), 0,
                "is a frame of level " + std::to_string(level) + "; the dataset has " +
                    std::to_string(dataset.mesh.levels.size()) + " level(s)");
  if (levelGiven && resolveLevel(dataset.mesh, levelOption) != level)
    throw Error("--level " + std::to_string(levelOption) + ": the run's frames are of level " +
                std::to_string(level) + "; leave --level out");
  if (input.binding && input.binding->level != level)
    throw Error(input.path.string(), 0,
                "is bound to level " + std::to_string(input.binding->level) +
                    ", the run's frames are of level " + std::to_string(level) +
                    ": bind the surface to level " + std::to_string(level) +
                    " or give the plain surface");
  return level;
}

// OUT.png -> OUT_00007.png: the image of the run's frame `index`.
std::filesystem::path frameImage(const std::filesystem::path& output, std::size_t index) {
  char number[16];
  std::snprintf(number, sizeof number, "_%05zu", index);
  std::filesystem::path image = output;
  image.replace_filename(output.stem().string() + number + output.extension().string());
  return image;
}

// Frames the camera on the run's whole motion, so that no frame leaves the
// picture (a drop's start lies above the rest shape): every frame is read
// (and checked) once before any is drawn.
void frameMotion(AnimatedScene& scene, const RecordedRun& recorded, const TetMesh& rest,
                 const std::string& restName) {
  BoundingBox motion;
  for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
    const BoundingBox box = boundingBox(recorded.read(i, rest, restName).positions);
    motion.extend(box.min);
    motion.extend(box.max);
  }
  scene.frame(motion);
}

// Draws frame `i` of the run (the fur's drag from the time since the one before).
void drawFrame(AnimatedScene& scene, const RecordedRun& recorded, std::size_t i,
               const TetMesh& rest, const std::string& restName) {
  const FrameState state = recorded.read(i, rest, restName);
  scene.draw(state.positions, i > 0 ? recorded.time(i) - recorded.time(i - 1) : 0);
}

// Draws every control frame of a recorded run to its own image, replacing
// the images of an earlier drawing under the same name; a frame that cannot
// be drawn removes the images drawn before it, and the folders made for them.
void drawRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest) {
  requireWritableLocation(frameImage(output, 0));
  const std::filesystem::path madeFolder = outermostMissingFolder(output);  // (the images make it)
  frameMotion(scene, recorded, rest, restName);
  std::vector<std::filesystem::path> written;
  try {
    for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
      drawFrame(scene, recorded, i, rest, restName);
      written.push_back(frameImage(output, i));
      scene.view().writePng(written.back());
    }
  } catch (...) {
    for (const std::filesystem::path& image : written) std::filesystem::remove(image);
    if (!madeFolder.empty()) std::filesystem::remove_all(madeFolder);
    throw;
  }
  // The images of an earlier, longer run drawn under this name would follow
  // this run's in a film made of the folder's images.
  for (std::size_t i = recorded.frameCount(); std::filesystem::exists(frameImage(output, i)); ++i)
    std::filesystem::remove(frameImage(output, i));
}

// A movie's rate for frames `seconds` apart, so that it plays in real time
// (1/60 s: 60 frames/s); 1 to 1000.
int framesPerSecond(double seconds) {
  if (!(seconds > 0)) return 1;
  return static_cast<int>(std::clamp(std::lround(1 / seconds), 1L, 1000L));
}

// A recorded run's frames as fast as they were recorded (31 frames over 1 s:
// 30 frames/s).
int framesPerSecond(const RecordedRun& recorded) {
  const std::size_t n = recorded.frameCount();
  const double span = recorded.time(n - 1) - recorded.time(0);
  return n < 2 ? 1 : framesPerSecond(span / static_cast<double>(n - 1));
}

// Films a recorded run: every control frame into one movie (.ogv), written
// atomically (nothing is left where a frame cannot be drawn).
void filmRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest) {
  requireWritableLocation(output);
  frameMotion(scene, recorded, rest, restName);
  writeFileAtomically(output, [&](const std::filesystem::path& temporary) {
    MovieFile movie(temporary, framesPerSecond(recorded));
    for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
      drawFrame(scene, recorded, i, rest, restName);
      movie.add(scene.view().capture());
    }
    movie.finish();
  });
}

void run(const RenderArgs& a, const CLI::App& cmd) {
  SceneOptions o;
  const ImageSize size = checkedImageSize(a.size);
  o.width = size.width;
  o.height = size.height;
  o.path = parseRenderPath(a.path);
  o.camera = parseCameraPreset(a.camera);
  o.level = a.level;
  o.scenario = a.scenario;
  o.control = a.control;
  o.texture = a.texture;
  o.datasetName = a.dataset.string();
  parseControlMeshStyle(o.control);  // reject typos before any work
  if (const auto option = givenOptionOf(cmd, kFurGroup); option && !hasFur(o.path))
    throw Error(*option + ": applies to the fur paths (fur-cpu, fur-gpu), not to " + a.path);
  if (!a.run.empty() && a.frames > 0)
    throw Error("--frames: simulates a new run; --run draws the recorded one: give one of them");
  const bool film = lowerExtension(a.output) == ".ogv";
  if (film && a.run.empty() && a.frames == 0)
    throw Error("-o " + a.output.string() +
                ": a movie is filmed of a run: give --frames N (simulated now) or --run RUN.pvd "
                "(recorded)");
  if (const auto option = givenScenarioOption(cmd); option && a.frames == 0)
    throw Error(*option + ": applies to simulated frames; give --frames N" +
                (a.run.empty() ? "" : " (--run draws a recorded run as it was simulated)"));
  const Dataset dataset = loadDataset(a.dataset);
  o.fur = furParameters(a, dataset.config);
  o.up = upAxisOf(a.scenario, dataset.config);
  if (hasFur(o.path) && o.texture.empty() && o.fur.colorTexture)
    o.texture = dataset.config.resolve(*o.fur.colorTexture);
  std::filesystem::path surfacePath = a.surface;
  if (surfacePath.empty()) {
    if (!dataset.config.surface)
      throw Error(a.dataset.string(), 0, "names no default surface; give --surface");
    surfacePath = dataset.config.resolve(*dataset.config.surface);
  }
  requireNotAnInput(a.output, {o.texture, surfacePath, a.dataset});
  const std::optional<RecordedRun> recorded =
      a.run.empty() ? std::nullopt : std::optional<RecordedRun>(a.run);
  // A binding from `tetskin bind` is drawn as it is (method, offset, level).
  const SurfaceInput input = readSurfaceInput(surfacePath, dataset.mesh);
  const bool levelGiven = cmd.count("--level") > 0;
  const int level = recorded ? runLevel(*recorded, input, dataset, a.level, levelGiven)
                             : commandLevel(input, dataset.mesh, a.level, levelGiven);
  o.level = level;
  const SurfaceMesh& surface = input.surface;
  o.scenario.parameters = scenarioParameters(
      cmd, a.scenario, dataset.mesh.levels[static_cast<std::size_t>(level)].nodeCount);
  AnimatedScene scene(dataset, input, o);
  if (recorded) {
    const std::string restName = "level " + std::to_string(level) + " of " + a.dataset.string();
    const TetMesh rest = extractLevel(dataset.mesh, level);
    if (film)
      filmRun(scene, *recorded, a.output, restName, rest);
    else
      drawRun(scene, *recorded, a.output, restName, rest);
    const std::size_t frames = recorded->frameCount();
    std::printf("drew %zu frames of %s (t %g .. %g s), path %s, level %d, %dx%d\n", frames,
                a.run.c_str(), recorded->time(0), recorded->time(frames - 1), toString(o.path),
                level, o.width, o.height);
    std::printf("  renderer: %s\n", scene.view().glRenderer().c_str());
    if (film)
      std::printf("wrote %s (%zu frames at %d frames/s)\n", a.output.c_str(), frames,
                  framesPerSecond(*recorded));
    else
      std::printf("wrote %s .. %s\n", frameImage(a.output, 0).c_str(),
                  frameImage(a.output, frames - 1).c_str());
    return;
  }
  FrameStats s;
  int rate = 0;
  if (film) {  // every simulated frame into the movie, in real time
    rate = framesPerSecond(scene.frameSeconds());
    writeFileAtomically(a.output, [&](const std::filesystem::path& temporary) {
      MovieFile movie(temporary, rate);
      s = scene.run(a.frames, [&] { movie.add(scene.view().capture()); });
      movie.finish();
    });
  } else {
    s = scene.run(a.frames);
    scene.view().writePng(a.output);
  }
  if (a.frames > 0) {
    std::printf("%d frames, path %s, %lld triangles, level %d (%lld tetrahedra), %dx%d\n", a.frames,
                toString(o.path), static_cast<long long>(surface.triangleCount()), scene.level(),
                static_cast<long long>(scene.elementCount()), o.width, o.height);
    if (scene.furShells() > 0) std::printf("  fur: %d shells drawn\n", scene.furShells());
    std::printf(
        "  %.1f frames/s; per frame: simulation %.2f ms, deformation %.2f ms, upload %.2f ms, draw "
        "%.2f ms\n",
        s.framesPerSecond(), 1e3 * s.simulation / a.frames, 1e3 * s.deformation / a.frames,
        1e3 * s.upload / a.frames, 1e3 * s.draw / a.frames);
  }
  std::printf("  renderer: %s\n", scene.view().glRenderer().c_str());
  if (film)
    std::printf("wrote %s (%d frames at %d frames/s)\n", a.output.c_str(), a.frames, rate);
  else
    std::printf("wrote %s\n", a.output.c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render",
      "Headless rendering of a dataset's bound surface to PNG (needs X: use xvfb-run -a)");
  cmd->add_option("DATASET", a->dataset, "dataset (.json)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--surface", a->surface, "surface (default: the dataset's surface)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--path", a->path, "cpu, gpu-1pass, gpu-2pass, fur-cpu or fur-gpu")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->output,
                  "image (.png); with --run, the images OUT_00000.png, ... or one movie (.ogv)")
      ->required()
      ->check(fileEnding(std::vector<std::string>{".png", ".ogv"}));
  cmd->add_option("--texture", a->texture,
                  "colour texture (PNG) for a surface with texture coordinates; on fur paths it "
                  "colours the fur and its alpha 0 masks it (default there: the config's "
                  "fur.color_texture)")
      ->check(CLI::ExistingFile);
  // (The fur values' ranges are io furParameterProblem's, checked in run();
  // the checks here only keep CLI11's "Could not convert" from the user.)
  cmd->add_option("--fur-shells", a->furShells, "most shells drawn")
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-min-shells", a->furMinShells, "fewest shells when adaptive")
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-adaptive", a->furAdaptive, "fewer shells when the fur is few pixels tall")
      ->check(trueOrFalse())
      ->group(kFurGroup);
  cmd->add_option("--fur-length", a->furLength, "fur length / bounding-box diagonal")
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-density", a->furDensity, "share of texels with a hair")
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-texture-size", a->furTextureSize, "fur texture edge in texels")
      ->check(anyWholeNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-repeats", a->furRepeats, "fur texture tiles across the diagonal")
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-seed", a->furSeed, "random seed of the fur texture")
      ->check(wholeNumber(0, std::numeric_limits<std::uint32_t>::max()))
      ->group(kFurGroup);
  cmd->add_option("--fur-drag", a->furDrag, "seconds of velocity the tips trail by (0: static)")
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-lighting", a->furLighting, "velvet or kajiya-kay")->group(kFurGroup);
  cmd->add_option("--fur-velvet", a->furVelvet, "highlight offset off the mirror direction")
      ->check(finiteNumber())
      ->group(kFurGroup);
  cmd->add_option("--fur-fins", a->furFins, "silhouette fins")
      ->check(trueOrFalse())
      ->group(kFurGroup);
  cmd->add_option("--level", a->level, kLevelHelp)->check(anyWholeNumber());
  cmd->add_option("--size", a->size, "WIDTHxHEIGHT")->capture_default_str()->check(imageSize());
  cmd->add_option("--camera", a->camera, "front, side, top or iso")->capture_default_str();
  cmd->add_option("--control", a->control, "control mesh: none, surface, wireframe or shrink")
      ->capture_default_str();
  cmd->add_option("--frames", a->frames,
                  "simulate and draw N frames, report frames/s and a breakdown")
      ->check(wholeNumber(0));
  cmd->add_option("--run", a->run,
                  "draw a recorded run (.pvd from simulate or the GUI's Record): each control "
                  "frame to its own image, OUT_00000.png, OUT_00001.png, ... on the frames' level")
      ->check(CLI::ExistingFile)
      ->check(fileEnding(".pvd"));
  addScenarioOptions(*cmd, a->scenario);
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
