// SPDX-License-Identifier: AGPL-3.0-or-later
// `tetskin compare`: which control level is enough (issue #55). The same
// scenario on several levels (or runs recorded earlier), the same surface
// bound to each, and per vertex and frame how far each level's surface lies
// from the reference level's, with the cost per step beside it.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Commands.h"
#include "OptionChecks.h"
#include "Progress.h"
#include "RunOptions.h"
#include "SurfaceInput.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/LevelComparison.h"
#include "tetskin/session/SceneFile.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/vtkio/RunRecorder.h"

namespace tetskin::cli {
namespace {

constexpr const char* kMotionGroup = "Motion";

struct CompareArgs {
  std::filesystem::path dataset, surface, output, table;
  std::vector<int> levels;
  int reference = -1, steps = static_cast<int>(recording_option::kSteps.defaultValue),
      every = static_cast<int>(recording_option::kEvery.defaultValue);
  std::vector<std::filesystem::path> runs;
  RunArgs run;
  bool quiet = false;
};

// The table beside the series: OUT.csv for OUT.pvd.
std::filesystem::path tableOf(const CompareArgs& a) {
  if (!a.table.empty()) return a.table;
  std::filesystem::path table = a.output;
  return table.replace_extension(".csv");
}

void checkOptions(const CompareArgs& a, const CLI::App& cmd) {
  if (a.runs.empty() && a.steps == 0)
    throw Error(std::string(recording_option::kSteps.flag) +
                ": 0 steps leave the levels at rest, with nothing to compare: give 1 or more");
  if (!a.runs.empty()) {
    // What would be simulated is read from the runs instead.
    for (const char* option :
         {"--levels", "--reference", recording_option::kSteps.flag, recording_option::kEvery.flag})
      if (cmd.count(option) > 0)
        throw Error(std::string(option) + ": compares simulated levels; --runs compares " +
                    "recorded runs (the first the reference) frame by frame");
    if (const std::optional<std::string> given = givenScenarioOption(cmd))
      throw Error(*given + ": compares simulated levels; --runs compares recorded runs");
    std::optional<std::string> given = givenOptionOf(cmd, kMaterialGroup);
    if (!given) given = givenName(cmd, simulation_option::kTimeStep);
    if (!given) given = givenName(cmd, scenario_option::kFloorHeight);
    for (const char* option : {simulation_option::kSolver.flag, simulation_option::kTangent.flag,
                               scenario_option::kGravity.flag, kUpOption.flag})
      if (!given && cmd.count(option) > 0) given = option;
    if (given) throw Error(*given + ": compares simulated levels; --runs compares recorded runs");
  }
  // A node list names nodes of one level; the levels compared have others.
  if (!a.run.scenario.fixedNodes.empty())
    throw Error(std::string(scenario_option::kFixedNodes.flag) +
                ": names nodes of one level, and compare runs several: hold nodes by " +
                scenario_option::kFixedBox.flag + ", which takes each level's nodes in the box");
  if (!a.run.scenario.loads.empty())
    throw Error(std::string(scenario_option::kLoads.flag) +
                ": names nodes of one level, and compare runs several: compare recorded runs "
                "(--runs) whose loads were given per level");
  if (!a.run.scenario.loadFaces.empty())
    throw Error(std::string(scenario_option::kLoadFaces.flag) +
                ": names faces of one level, and compare runs several: select them by " +
                scenario_option::kLoadBox.flag + ", which takes each level's faces in the box");
  checkRunOptions(a.run, cmd);
  const std::filesystem::path table = tableOf(a);
  requireNotAnInput(a.output, {a.dataset, a.surface});
  requireNotAnInput(table, {a.dataset, a.surface, a.output});
  for (const std::filesystem::path& run : a.runs) requireNotAnInput(a.output, {run});
  requireWritableLocation(table);  // before the runs, not after them
}

// The levels to simulate, resolved, in the order given, with the reference
// (appended when missing); and which of them is the reference.
std::pair<std::vector<int>, std::size_t> comparedLevels(const CompareArgs& a,
                                                        const MultiLevelTetMesh& mesh) {
  const int reference = resolveLevel(mesh, a.reference);
  std::vector<int> levels;
  if (a.levels.empty())
    for (int level = 0; level < mesh.levelCount(); ++level) levels.push_back(level);
  for (int level : a.levels) {
    const int resolved = resolveLevel(mesh, level);
    if (std::find(levels.begin(), levels.end(), resolved) != levels.end())
      throw Error("--levels: level " + std::to_string(resolved) + " is given twice");
    levels.push_back(resolved);
  }
  auto at = std::find(levels.begin(), levels.end(), reference);
  if (at == levels.end()) at = levels.insert(levels.end(), reference);
  if (levels.size() < 2)
    throw Error("--levels: level " + std::to_string(reference) +
                " alone: name another level to compare with the reference (" +
                std::to_string(mesh.levelCount()) + " levels in the dataset)");
  return {levels, static_cast<std::size_t>(at - levels.begin())};
}

std::string percent(double value, double diagonal) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", 100 * value / (diagonal > 0 ? diagonal : 1));
  return text;
}

std::string degrees(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Every frame compared (recorded as it goes), then the table written.
void compareAll(const CompareArgs& a, LevelComparison& comparison) {
  comparison.record(a.output);
  Progress progress(a.quiet);
  comparison.compare();
  if (comparison.simulated()) {
    for (int i = 0; i < a.steps; ++i) {
      comparison.advance();
      if ((i + 1) % a.every == 0 || i + 1 == a.steps) comparison.compare();
      progress.update("compare", static_cast<std::size_t>(i + 1),
                      static_cast<std::size_t>(a.steps));
    }
  } else {
    for (std::size_t f = 1; f < comparison.recordedFrames(); ++f) {
      comparison.advance();
      comparison.compare();
      progress.update("compare", f + 1, comparison.recordedFrames());
    }
  }
  comparison.writeFrameTable(tableOf(a));
}

// A row's errors: distance (% of `diagonal`) and normal angle, under the
// table's two last headings.
std::string errorColumns(const ErrorSpread& e, double diagonal) {
  const std::string distance = percent(e.distance.max, diagonal) + " / " +
                               percent(e.distance.p99, diagonal) + " / " +
                               percent(e.distance.median, diagonal);
  char columns[160];
  std::snprintf(
      columns, sizeof columns, "%-34s %s", distance.c_str(),
      (degrees(e.angle.max) + " / " + degrees(e.angle.p99) + " / " + degrees(e.angle.median))
          .c_str());
  return columns;
}

void report(const CompareArgs& a, const LevelComparison& comparison, bool scene) {
  const double diagonal = comparison.diagonal();
  if (comparison.simulated()) {
    const SimulationSession& first = *comparison.session(0);
    std::printf(
        "compared %zu levels of %s over %d steps of %g s, scenario %s, reference level %d%s\n",
        comparison.runCount(), a.dataset.c_str(), a.steps, first.options().timeStep,
        first.scenario().name(), comparison.level(comparison.reference()),
        scene ? " (every body on the level)" : "");
  } else {
    std::printf("compared %zu recorded runs of %s over %zu frames, reference %s (level %d)\n",
                comparison.runCount(), a.dataset.c_str(), comparison.recordedFrames(),
                a.runs.front().c_str(), comparison.level(0));
  }
  const std::size_t bodies = comparison.bodyCount();
  if (scene)
    std::printf(
        "  skins of %zu bod%s: %lld vertices, diagonal %s; errors over every vertex of %zu "
        "frames\n",
        bodies, bodies == 1 ? "y" : "ies", static_cast<long long>(comparison.vertexCount()),
        formatNumber(diagonal).c_str(), comparison.frames().size());
  else
    std::printf(
        "  surface %s: %lld vertices, diagonal %s; errors over every vertex of %zu frames\n",
        a.surface.c_str(), static_cast<long long>(comparison.vertexCount()),
        formatNumber(diagonal).c_str(), comparison.frames().size());
  std::printf("  %-6s %9s %9s   %-34s %s\n", "level", "elements", "ms/step",
              "distance max / p99 / median", "normal angle max / p99 / median (deg)");
  for (std::size_t r = 0; r < comparison.runCount(); ++r) {
    const Index elements = comparison.elementCount(r);
    char cost[32] = "-";
    if (comparison.simulated())
      std::snprintf(cost, sizeof cost, "%.3g", 1e3 * comparison.meanStepSeconds(r));
    const std::string name =
        std::to_string(comparison.level(r)) + (r == comparison.reference() ? " ref" : "");
    if (r == comparison.reference()) {
      std::printf("  %-6s %9lld %9s   %-34s %s\n", name.c_str(), static_cast<long long>(elements),
                  cost, "(reference)", "");
      continue;
    }
    std::printf("  %-6s %9lld %9s   %s\n", name.c_str(), static_cast<long long>(elements), cost,
                errorColumns(comparison.overall(r), diagonal).c_str());
    // Per body: its skin's vertices, against its own diagonal.
    if (bodies > 1)
      for (std::size_t b = 0; b < bodies; ++b)
        std::printf("  %-26s   %s\n", ("  body " + std::to_string(b)).c_str(),
                    errorColumns(comparison.overall(r, b), comparison.bodyDiagonal(b)).c_str());
  }
  std::printf("  (distances as %% of the diagonal%s; absolute values in the table)\n",
              bodies > 1 ? ", a body's of its own" : "");
  const RunRecorder& recorder = *comparison.recorder();
  std::printf("wrote %s (%lld frames of %zu surfaces)\n", recorder.path().c_str(),
              static_cast<long long>(recorder.frames()), comparison.runCount());
  std::printf("wrote %s\n", tableOf(a).c_str());
}

// A scene on each level compared: every body on that level (the levels
// numbered as the first body's dataset numbers them), the command line's
// options over the scene's run, as simulate takes them.
std::unique_ptr<LevelComparison> sceneComparison(CompareArgs& a, const CLI::App& cmd) {
  if (!a.runs.empty())
    throw Error(
        "--runs: compares recorded runs of one dataset; a scene's levels are compared by "
        "simulating them (--levels)");
  if (!a.surface.empty())
    throw Error(a.surface.string() + ": " + a.dataset.string() +
                " is a scene, whose skins are its bodies' surfaces: give no SURFACE");
  const Scene scene = readScene(a.dataset);
  const Dataset first = loadDataset(scene.bodies.front().dataset);
  const auto [levels, reference] = comparedLevels(a, first.mesh);
  std::vector<SceneLevel> runs;
  for (const int level : levels) {
    Scene atLevel = scene;
    for (SceneBody& body : atLevel.bodies) body.level = level;
    SceneLevel& compared = runs.emplace_back(SceneLevel{level, loadScene(atLevel), {}});
    SceneRun& run = compared.scene;
    applyRunOptions(a.run, cmd,
                    run.dataset.mesh.levels[static_cast<std::size_t>(run.level)].nodeCount,
                    run.request);
    compared.spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  }
  if (!givenName(cmd, recording_option::kSteps)) a.steps = runs.front().scene.steps;
  return std::make_unique<LevelComparison>(std::move(runs), reference);
}

void run(CompareArgs& a, const CLI::App& cmd) {
  checkOptions(a, cmd);
  if (isSceneFile(a.dataset)) {
    std::unique_ptr<LevelComparison> comparison = sceneComparison(a, cmd);
    compareAll(a, *comparison);
    report(a, *comparison, true);
    return;
  }
  if (a.surface.empty())
    throw Error("SURFACE: the surface compared is required (a scene's skins are its own)");
  const Dataset dataset = loadDataset(a.dataset);
  // A binding's surface is bound anew to every level.
  const SurfaceInput input = readSurfaceInput(a.surface, dataset.mesh);
  std::unique_ptr<LevelComparison> comparison;
  if (a.runs.empty()) {
    const auto [levels, reference] = comparedLevels(a, dataset.mesh);
    std::vector<RunSpec> specs;
    for (int level : levels)
      specs.push_back(runSpec(a.run, cmd, dataset, level, a.dataset.string()));
    comparison = std::make_unique<LevelComparison>(dataset.mesh, input.surface, specs, reference,
                                                   a.dataset.generic_string());
  } else {
    comparison = std::make_unique<LevelComparison>(dataset.mesh, input.surface, a.runs,
                                                   a.dataset.generic_string());
  }
  compareAll(a, *comparison);
  report(a, *comparison, false);
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Which level is enough: the same scenario on several levels, the same surface bound to "
      "each; per vertex and frame the distance and normal angle against the reference level, "
      "with each level's cost per step");
  addDatasetOrSceneArgument(
      *cmd, a->dataset,
      "every body on each level compared, its skins the surface, errors also per body");
  cmd->add_option("SURFACE", a->surface,
                  "the surface (OBJ, PLY, STL, VTP; a binding's surface), bound to every level "
                  "by its closest boundary point with the normal offset (required, but for a "
                  "scene)")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output,
                  "time series OUT.pvd: per frame the surface as each level deforms it (a part "
                  "per level), with SurfaceError, RelativeError, NormalAngle, VonMisesStress and "
                  "EquivalentStrain (frames go to OUT_frames/)")
      ->required()
      ->check(fileEnding(".pvd"));
  cmd->add_option("--table", a->table,
                  "the errors per frame and level (.csv; default: OUT.csv beside OUT.pvd)")
      ->check(fileEnding(".csv"));
  cmd->add_option("--levels", a->levels,
                  "the levels compared, e.g. 0,1 (negative from the finest; default: all)")
      ->delimiter(',')
      ->check(anyWholeNumber())
      ->group(kMotionGroup);
  cmd->add_option("--reference", a->reference,
                  "the level the others are measured against (default -1: the finest)")
      ->check(anyWholeNumber())
      ->group(kMotionGroup);
  addNumberOption(*cmd, recording_option::kSteps, a->steps)->group(kMotionGroup);
  addNumberOption(*cmd, recording_option::kEvery, a->every,
                  "compare every k-th step (and the last)")
      ->group(kMotionGroup);
  cmd->add_option("--runs", a->runs,
                  "compare runs recorded by simulate (RUN.pvd, two or more, the first the "
                  "reference; each on the level its frames name) instead of simulating")
      ->expected(2, 1 << 20)
      ->check(CLI::ExistingFile)
      ->group(kMotionGroup);
  addRunOptions(*cmd, a->run);
  cmd->add_flag("-q,--quiet", a->quiet, "no progress on stderr");
  addCompressOption(*cmd);
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
