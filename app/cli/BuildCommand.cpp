// SPDX-License-Identifier: AGPL-3.0-or-later
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "Commands.h"
#include "OptionChecks.h"
#include "Progress.h"
#include "tetskin/core/Error.h"
#include "tetskin/meshing/DatasetBuild.h"

namespace tetskin::cli {
namespace {

struct BuildArgs {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path output;
  std::string lodSeries;
  int lodInputs = 0;
  std::string mesher = toString(BuildOptions{}.mesher);
  std::vector<double> qualities = BuildOptions{}.qualities;
  std::string up = toString(BuildOptions{}.up);
  std::string wrap = toString(BuildOptions{}.wrap.mode);
  BuildOptions options;
  bool quiet = false;
};

std::vector<std::filesystem::path> inputPaths(const BuildArgs& a) {
  std::vector<std::filesystem::path> paths = a.inputs;
  if (!a.lodSeries.empty()) {
    if (a.lodInputs < 1) throw Error("--lod-series needs --inputs K (K >= 1)");
    for (int k = 0; k < a.lodInputs; ++k)
      paths.emplace_back(a.lodSeries + "_" + std::to_string(k) + ".obj");
  }
  if (paths.empty()) throw Error("no input: give surface files or --lod-series NAME --inputs K");
  return paths;
}

void run(BuildArgs& a) {
  a.options.mesher = fromName<MesherKind>(a.mesher);
  a.options.qualities = a.qualities;
  a.options.up = fromName<UpAxis>(a.up);
  a.options.wrap.mode = fromName<WrapMode>(a.wrap);
  Progress progress(a.quiet);
  BuildEvents events;
  events.log = [&](const std::string& line) { progress.log(line); };
  events.progress = [&](const std::string& stage, std::size_t done, std::size_t total) {
    progress.update(stage, done, total);
  };
  const DatasetBuild build = buildDatasetFiles(inputPaths(a), a.output, a.options, events);
  const BuildResult& result = build.result;
  const std::filesystem::path& json = build.config;
  progress.log("");

  // The fidelity columns: input -> level, mean and max, in % of the input's
  // bounding-box diagonal (LevelFidelity.h).
  std::printf("%-5s %9s %8s  %-8s %-16s %8s %8s %8s %8s  %s\n", "level", "elements", "nodes",
              "mesher", "quality", "min dih", "max r/e", "mean %", "max %", "input");
  for (std::size_t k = 0; k < result.chosen.size(); ++k) {
    const CandidateReport& c = result.candidates[static_cast<std::size_t>(result.chosen[k])];
    const LevelFidelity f = c.fidelity.value_or(LevelFidelity{});
    const double d = f.diagonal > 0 ? f.diagonal : 1.0;
    std::printf("%-5zu %9lld %8lld  %-8s %-16s %8.2f %8.3f %8.3f %8.3f  %s\n", k,
                static_cast<long long>(c.elements), static_cast<long long>(c.nodes),
                c.mesher.c_str(), c.label.c_str(), c.statistics.minDihedralDeg,
                c.statistics.maxRadiusEdge, 100 * f.inputToLevelMean / d,
                100 * f.inputToLevelMax / d, c.input.c_str());
  }
  for (std::size_t k = 0; k < result.chosen.size(); ++k) {
    const CandidateReport& c = result.candidates[static_cast<std::size_t>(result.chosen[k])];
    if (c.fidelity)
      std::printf("level %zu against the input: %s\n", k, describe(*c.fidelity).c_str());
  }
  for (std::size_t k = 0; k < result.chosen.size(); ++k) {
    const CandidateReport& c = result.candidates[static_cast<std::size_t>(result.chosen[k])];
    if (c.wrap) std::printf("level %zu was meshed from a wrap: %s\n", k, describe(*c.wrap).c_str());
  }
  std::size_t failed = 0;
  for (const CandidateReport& c : result.candidates) failed += c.ok ? 0 : 1;
  std::printf("%zu candidates meshed in %.2f s with %d job(s), %zu failed",
              result.candidates.size(), result.meshingSeconds, a.options.jobs, failed);
  if (result.skippedCandidates > 0)
    std::printf(", %zu skipped (finer than one above the largest target)",
                result.skippedCandidates);
  std::printf("\n");
  std::printf("wrote %s (+ .node, .ele)\n", json.c_str());
}

}  // namespace

void addBuildCommand(CLI::App& app) {
  auto a = std::make_shared<BuildArgs>();
  a->options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* cmd = app.add_subcommand(
      "build",
      "Model generation: repair OBJ/PLY/STL surfaces, tetrahedralize them at several qualities,\n"
      "choose the levels and write one multi-level dataset OUT.node, OUT.ele, OUT.json");
  cmd->add_option("IN", a->inputs, "input surfaces (levels of detail of one object)")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "output name OUT (writes OUT.node, OUT.ele, OUT.json)")
      ->required();
  addNumberOption(*cmd, build_option::kLevels, a->options.levels);
  addNumberOption(*cmd, build_option::kMinElements, a->options.minElements);
  addNumberOption(*cmd, build_option::kMaxElements, a->options.maxElements);
  addEnumOption(*cmd, build_option::kMesher, a->mesher);
  cmd->add_option(build_option::kQualities.flag, a->qualities, build_option::kQualities.help)
      ->delimiter(',')
      ->capture_default_str()
      ->check(numberAbove(1));
  cmd->add_option("--lod-series", a->lodSeries, "read NAME_0.obj .. NAME_{K-1}.obj");
  cmd->add_option("--inputs", a->lodInputs, "K, the number of files of --lod-series")
      ->check(wholeNumber(1));
  cmd->add_flag("--decimate", a->options.decimate,
                "derive coarser input levels of detail from the finest surface");
  cmd->add_flag("--size-to-targets", a->options.sizeToTargets,
                "also mesh under element size bounds aimed at the level targets that no\n"
                "quality meets (TetGen -a, Netgen maxh): for shapes such as boxes");
  cmd->add_flag("--accept-unfaithful", a->options.acceptUnfaithful,
                "write levels that lie off the input beyond their fidelity bound (half their\n"
                "element size on average, twice it at worst) when no faithful candidate is\n"
                "near their target; without it, build stops and says which and why");
  addEnumOption(*cmd, wrap_option::kMode, a->wrap);
  addNumberOption(*cmd, wrap_option::kAlpha, a->options.wrap.alpha);
  addNumberOption(*cmd, wrap_option::kOffset, a->options.wrap.offset);
  // (Default: all cores, set before parsing.)
  addNumberOption(*cmd, build_option::kJobs, a->options.jobs)->default_str("");
  addNumberOption(*cmd, build_option::kTimeout, a->options.timeoutSeconds);
  addEnumOption(*cmd, kUpOption, a->up,
                " in the inputs (written to the config; simulation and cameras follow it)");
  cmd->add_flag("-q,--quiet", a->quiet, "no progress or repair report on stderr");
  cmd->callback([a] { run(*a); });
}

}  // namespace tetskin::cli
