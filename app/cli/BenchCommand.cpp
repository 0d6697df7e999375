// SPDX-License-Identifier: AGPL-3.0-or-later
// `tetskin bench`: the report's Table 6.1 on our data, next to the 2005 numbers.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "AnimatedScene.h"
#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin::cli {
namespace {

// The bundled data: the source tree's for a build, else the installed package's.
std::filesystem::path defaultDataDir() {
  if (std::filesystem::exists(std::filesystem::path(TETSKIN_DATA_DIR) / "bunny.json"))
    return TETSKIN_DATA_DIR;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return exe.parent_path().parent_path() / "share" / "tetskin" / "data";
}

struct BenchArgs {
  std::filesystem::path data = defaultDataDir();
  int frames = 60;
  // (Not render's 800x600: bench's rows of Table 6.1 are timed at 640x480.)
  std::string size = "640x480";
  bool json = false;
};

// Table 6.1 of the report: Windows XP, P4 2.8 GHz, GeForce 6800 GT (CPU, GPU
// 1-pass, GPU 2-pass, fur CPU, fur GPU).
struct ReportRow {
  const char* model;
  const char* surface;
  int level;
  const char* reported;
  const char* texture = nullptr;
};

const ReportRow kRows[] = {
    {"Bunny 8k, 630 tets", "bunny_8k.obj", 0, "155 / 144 / 162 / 20.0 / 39.0"},
    {"BunnyTex 8k, 630 tets", "bunny_8k_tex.obj", 0, "157 / 141 / 157 / 18.7 / 33.0",
     "bunny_texture.png"},
    {"Bunny 8k, 11206 tets", "bunny_8k.obj", 2, "57 / 53 / 55 / 15.7 / 26.0"},
    {"Bunny 64k, 630 tets", "bunny_64k.obj", 0, "33 / 52 / 73 / 2.5 / 12.5"},
    {"Bunny 64k, 11206 tets", "bunny_64k.obj", 2, "24.5 / 27.5 / 37 / 2.0 / 11.0"},
};

void run(const BenchArgs& a) {
  SceneOptions o;
  const ImageSize size = checkedImageSize(a.size);
  o.width = size.width;
  o.height = size.height;
  const Dataset dataset = loadDataset(a.data / "bunny.json");
  o.fur = dataset.config.fur;
  nlohmann::json results = nlohmann::json::array();
  std::string renderer;
  if (!a.json) {
    std::printf(
        "Table 6.1 on this machine: frames/s, wobble animation, per-pixel lighting, %dx%d, %d "
        "frames\n",
        o.width, o.height, a.frames);
    std::printf("%-24s %7s %9s %10s %10s %8s %8s   %s\n", "model", "tets", "cpu", "gpu-1pass",
                "gpu-2pass", "fur-cpu", "fur-gpu", "report 2005 (cpu/1p/2p/fur-cpu/fur-gpu)");
  }
  for (const ReportRow& row : kRows) {
    const SurfaceInput input{a.data / row.surface, readObj(a.data / row.surface), std::nullopt};
    const SurfaceMesh& surface = input.surface;
    o.level = row.level;
    o.texture = row.texture ? a.data / row.texture : std::filesystem::path();
    nlohmann::json entry = {
        {"model", row.model},
        {"triangles", surface.triangleCount()},
        {"tets", dataset.mesh.levels[static_cast<std::size_t>(row.level)].elementCount},
        {"report_2005", row.reported}};
    double fps[5] = {0, 0, 0, 0, 0};
    for (RenderPath path : {RenderPath::Cpu, RenderPath::Gpu1Pass, RenderPath::Gpu2Pass,
                            RenderPath::FurCpu, RenderPath::FurGpu}) {
      o.path = path;
      AnimatedScene scene(dataset, input, o);
      const FrameStats s = scene.run(a.frames);
      fps[static_cast<int>(path)] = s.framesPerSecond();
      entry[toString(path)] = {{"fps", s.framesPerSecond()},
                               {"simulation_ms", 1e3 * s.simulation / a.frames},
                               {"deformation_ms", 1e3 * s.deformation / a.frames},
                               {"upload_ms", 1e3 * s.upload / a.frames},
                               {"draw_ms", 1e3 * s.draw / a.frames}};
      renderer = scene.view().glRenderer();
    }
    results.push_back(entry);
    if (!a.json)
      std::printf("%-24s %7lld %9.1f %10.1f %10.1f %8.1f %8.1f   %s\n", row.model,
                  static_cast<long long>(entry["tets"].get<Index>()), fps[0], fps[1], fps[2],
                  fps[3], fps[4], row.reported);
  }
  if (a.json) {
    std::printf("%s\n",
                nlohmann::json({{"renderer", renderer}, {"rows", results}}).dump(2).c_str());
  } else {
    std::printf(
        "renderer: %s (the report: GeForce 6800 GT). Fur: %d shells at most (adaptive), "
        "the dataset's fur parameters.\n",
        renderer.c_str(), o.fur.shells);
    std::printf(
        "The 2005 tets were 630 and 11206; ours are the sample dataset's levels 0 and 2.\n");
  }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Reproduce the report's Table 6.1 (frames/s per render path) on the bundled bunnies");
  cmd->add_option("--data", a->data, "folder with bunny.json, bunny_8k.obj, bunny_64k.obj")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--frames", a->frames, "frames per measurement")
      ->capture_default_str()
      ->check(wholeNumber(1));
  cmd->add_option("--size", a->size, "WIDTHxHEIGHT")->capture_default_str()->check(imageSize());
  cmd->add_flag("--json", a->json, "machine-readable results");
  cmd->callback([a] { run(*a); });
}

}  // namespace tetskin::cli
