// SPDX-License-Identifier: AGPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "AnimatedScene.h"
#include "Commands.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::cli {
namespace {

struct RenderArgs {
  std::filesystem::path dataset, surface, output, texture;
  std::string path = "cpu", camera = "iso", control = "none", scenario = "wobble", size = "800x600";
  int level = -1, frames = 0;
};

void run(const RenderArgs& a) {
  SceneOptions o;
  if (std::sscanf(a.size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 16 ||
      o.height < 16 || o.width > 8192 || o.height > 8192)
    throw Error("--size must be WIDTHxHEIGHT between 16 and 8192, got '" + a.size + "'");
  o.path = parseRenderPath(a.path);
  o.camera = parseCameraPreset(a.camera);
  o.level = a.level;
  o.scenario = a.scenario;
  o.control = a.control;
  o.texture = a.texture;
  if (o.control != "none") parseControlMeshStyle(o.control);  // reject typos before any work
  const Dataset dataset = loadDataset(a.dataset);
  std::filesystem::path surfacePath = a.surface;
  if (surfacePath.empty()) {
    if (!dataset.config.surface)
      throw Error(a.dataset.string(), 0, "names no default surface; give --surface");
    surfacePath = dataset.config.resolve(*dataset.config.surface);
  }
  const SurfaceMesh surface = readSurface(surfacePath);
  AnimatedScene scene(dataset, surface, o);
  const FrameStats s = scene.run(a.frames);
  scene.view().writePng(a.output);
  if (a.frames > 0) {
    std::printf("%d frames, path %s, %lld triangles, level %d (%lld tetrahedra), %dx%d\n", a.frames,
                toString(o.path), static_cast<long long>(surface.triangleCount()), scene.level(),
                static_cast<long long>(scene.elementCount()), o.width, o.height);
    std::printf(
        "  %.1f frames/s; per frame: simulation %.2f ms, deformation %.2f ms, upload %.2f ms, draw "
        "%.2f ms\n",
        s.framesPerSecond(), 1e3 * s.simulation / a.frames, 1e3 * s.deformation / a.frames,
        1e3 * s.upload / a.frames, 1e3 * s.draw / a.frames);
  }
  std::printf("  renderer: %s\nwrote %s\n", scene.view().glRenderer().c_str(), a.output.c_str());
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
  cmd->add_option("--path", a->path, "cpu, gpu-1pass or gpu-2pass (fur-cpu, fur-gpu: not yet)")
      ->capture_default_str();
  cmd->add_option("-o,--output", a->output, "image (.png)")->required();
  cmd->add_option("--texture", a->texture,
                  "colour texture (PNG) for a surface with texture coordinates")
      ->check(CLI::ExistingFile);
  cmd->add_option("--level", a->level, "bound and simulated level (default: finest)");
  cmd->add_option("--size", a->size, "WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--camera", a->camera, "front, side, top or iso")->capture_default_str();
  cmd->add_option("--control", a->control, "control mesh: none, surface, wireframe or shrink")
      ->capture_default_str();
  cmd->add_option("--frames", a->frames,
                  "simulate and draw N frames, report frames/s and a breakdown")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--scenario", a->scenario, "scenario of the simulated frames")
      ->capture_default_str();
  cmd->callback([a] { run(*a); });
}

}  // namespace tetskin::cli
