// SPDX-License-Identifier: AGPL-3.0-or-later
#include <vtkUnstructuredGrid.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "Commands.h"
#include "MaterialOptions.h"
#include "OptionChecks.h"
#include "Progress.h"
#include "ScenarioOptions.h"
#include "SurfaceInput.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/StepLogFile.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct SimulateArgs {
  std::filesystem::path dataset, output, surface, initial, log;
  int steps = 120, level = -1, every = 1;
  std::string solver = "auto", coarseOperators = "galerkin", tangent = "full";
  ScenarioArgs scenario;
  SimulationOptions options;
  MaterialArgs material;  // over the config's elasticity
  bool quiet = false;
};

void run(SimulateArgs& a, const CLI::App& cmd) {
  // (Checked before any work, as a typo would be.)
  if (solverKindFromString(a.solver) == SolverKind::ConjugateGradient)
    for (const char* option : {"--coarse-reuse", "--coarse-operators"})
      if (cmd.count(option) > 0)
        throw Error(std::string(option) +
                    ": applies to the multigrid solver (--solver multigrid or auto), not to cg");
  if (!a.log.empty()) {
    requireNotAnInput(a.log, {a.dataset, a.surface, a.initial, a.output});
    requireWritableLocation(a.log);  // before the run, not after it
  }
  const Dataset dataset = loadDataset(a.dataset);
  // A binding from `tetskin bind` follows as it is, on its level.
  std::optional<SurfaceInput> input;
  if (!a.surface.empty()) input = readSurfaceInput(a.surface, dataset.mesh);
  const int level = input ? commandLevel(*input, dataset.mesh, a.level, cmd.count("--level") > 0)
                          : resolveLevel(dataset.mesh, a.level);
  a.options.solver = solverKindFromString(a.solver);
  a.options.tangent = tangentFromString(a.tangent);
  a.options.coarseOperators =
      a.coarseOperators == "galerkin" ? CoarseOperators::Galerkin : CoarseOperators::Rediscretized;
  a.options.material = materialOf(a.material, dataset.config.elasticity);
  a.options = uprightAlong(upAxisOf(a.scenario, dataset.config), a.options);
  const TetMesh rest = extractLevel(dataset.mesh, level);
  const SimulationOptions options =
      scenarioOptions(a.scenario.name, withGravityAndFloor(a.options, a.scenario), rest);
  const ScenarioParameters parameters = scenarioParameters(cmd, a.scenario, rest.nodes);
  std::unique_ptr<Scenario> scenario = makeScenario(a.scenario.name, parameters);
  Simulation sim(dataset.mesh, level, options, a.dataset.string());
  scenario->setUp(sim);
  if (!a.initial.empty()) {
    // The frame replaces the scenario's start (drop's lift too); its folder
    // is not the one this run writes, where frame 0 would overwrite it.
    std::error_code error;
    if (std::filesystem::equivalent(a.initial.parent_path().empty() ? "." : a.initial.parent_path(),
                                    RunRecorder::framesDirectory(a.output), error))
      throw Error(a.initial.string(), 0,
                  "is among the frames this run writes (-o " + a.output.string() +
                      "): write the new run to another name");
    const FrameState start = readSimulationFrame(
        a.initial, rest, "level " + std::to_string(level) + " of " + a.dataset.string());
    sim.setPositions(start.positions);
    sim.setVelocities(start.velocities);
  }
  if (const std::string warning = nodesBelowFloor(sim); !warning.empty())
    std::fprintf(stderr, "warning: %s\n", warning.c_str());

  // The bound surface, if any, follows every frame.
  std::unique_ptr<BoundSurface> bound;
  std::unique_ptr<SurfaceDeformer> deformer;
  if (input) {
    bound = std::make_unique<BoundSurface>();
    bound->binding = bindingAt(*input, dataset.mesh, level);
    bound->surface = std::move(input->surface);
    bound->dataset = a.dataset.generic_string();
    bound->deformed.emplace();  // (frame 0 too: the scenario's start, not always the rest)
    deformer =
        std::make_unique<SurfaceDeformer>(bound->surface, bound->binding, dataset.mesh.nodes);
  }

  RunRecorder recorder(a.output, sim.conditions());
  const LevelRange& range = dataset.mesh.levels[static_cast<std::size_t>(level)];
  Points3 controlAll = dataset.mesh.nodes;

  auto writeFrame = [&] {
    const SimulationState s = sim.state();
    if (deformer) {
      controlAll.middleRows(range.firstNode, range.nodeCount) = s.positions;
      deformer->deform(controlAll, bound->deformed->positions, bound->deformed->normals);
    }
    recorder.addFrame(s.time, sim.restMesh(), sim.frameFields(s), level,
                      deformer ? bound.get() : nullptr);
  };

  // --log: the start and every step, written at the end (and by a run cut
  // short, with the steps before it).
  std::vector<StepLogRow> log;
  auto logRow = [&](Index step, const StepStats* stats, double seconds) {
    if (a.log.empty()) return;
    StepLogRow row;
    row.step = step;
    row.time = sim.time();
    if (stats) {
      row.solver = toString(stats->solver);
      row.iterations = stats->iterations;
      row.residual = stats->residual;
      row.contacts = stats->contacts;
      row.assemblySeconds = stats->assemblySeconds;
      row.setupSeconds = stats->setupSeconds;
      row.solveSeconds = stats->solveSeconds;
      row.stepSeconds = seconds;
    }
    const Energies e = sim.energies();
    row.kinetic = e.kinetic;
    row.elastic = e.elastic;
    row.gravitational = e.gravitational;
    row.reaction = sim.supportReaction(sim.state());
    log.push_back(row);
  };

  Progress progress(a.quiet);
  writeFrame();
  logRow(0, nullptr, 0);
  double stepSeconds = 0;
  long iterations = 0, multigridSteps = 0;
  for (int i = 0; i < a.steps; ++i) {
    scenario->beforeStep(sim, sim.time());
    const auto start = std::chrono::steady_clock::now();
    StepStats stats;
    try {
      stats = sim.step();
    } catch (const Error& e) {  // e.g. diverged: say what the run leaves behind
      std::string kept = std::string(e.what()) + "; " + recorder.path().string() + " keeps the " +
                         std::to_string(recorder.frames()) + " frame(s) written before it";
      if (!a.log.empty()) {
        writeStepLog(a.log, log);
        kept += ", " + a.log.string() + " the " + std::to_string(i) + " step(s)";
      }
      throw Error(kept);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stepSeconds += seconds;
    logRow(i + 1, &stats, seconds);
    iterations += stats.iterations;
    multigridSteps += stats.solver == SolverKind::Multigrid;
    // Every k-th step, and the last one: a run ends with its end state written.
    if ((i + 1) % a.every == 0 || i + 1 == a.steps) writeFrame();
    progress.update("simulate", static_cast<std::size_t>(i + 1), static_cast<std::size_t>(a.steps));
  }
  const Energies e = sim.energies();
  std::printf(
      "simulated %d steps of %g s on level %d (%lld tetrahedra), scenario %s, solver %s%s%s, "
      "%s tangent\n",
      a.steps, options.timeStep, level, static_cast<long long>(sim.restMesh().elementCount()),
      scenario->name(), toString(options.solver),
      options.solver != SolverKind::ConjugateGradient ? ", " : "",
      options.solver != SolverKind::ConjugateGradient ? toString(options.coarseOperators) : "",
      toString(options.tangent));
  if (!a.initial.empty()) std::printf("  started from %s\n", a.initial.c_str());
  std::printf("  material: %s\n", describe(options.material).c_str());
  {
    // (Lengths are read as metres: a model written in millimetres shows
    // here as a body a thousand times too large.)
    const Eigen::Vector3d size = boundingBox(sim.restMesh().nodes).extent();
    const double mass = sim.nodeMasses().sum();
    std::printf("  body: %s x %s x %s m (%s up), mass %s kg\n", formatNumber(size.x()).c_str(),
                formatNumber(size.y()).c_str(), formatNumber(size.z()).c_str(),
                toString(options.up), formatNumber(mass).c_str());
  }
  std::printf("  %zu of %lld nodes fixed, ", sim.fixedNodes().size(),
              static_cast<long long>(sim.restMesh().nodeCount()));
  if (parameters.loads.size() > 0) {
    const Eigen::RowVector3d total = parameters.loads.colwise().sum();
    std::string until = std::isfinite(parameters.loadSeconds)
                            ? " for " + formatNumber(parameters.loadSeconds) + " s"
                            : "";
    if (!parameters.loadCurve.empty())
      until += ", scaled by a load curve of " + describe(parameters.loadCurve);
    std::printf(
        "%lld loaded (total force %s N%s), ",
        static_cast<long long>((parameters.loads.rowwise().squaredNorm().array() > 0).count()),
        commaSeparated(total.transpose()).c_str(), until.c_str());
  }
  std::printf("gravity %s m/s^2", commaSeparated(options.gravity).c_str());
  if (options.floorHeight)
    std::printf(", floor at %s = %s", toString(options.up),
                formatNumber(*options.floorHeight).c_str());
  std::printf("\n");
  if (a.steps > 0)
    std::printf("  %.1f steps/s, %.1f solver iterations per step\n",
                a.steps / std::max(stepSeconds, 1e-12), static_cast<double>(iterations) / a.steps);
  if (options.solver == SolverKind::Automatic && a.steps > 0) {
    // Before the first round of trials ends, neither solver has been found faster.
    const SolverChoice& choice = *sim.solverChoice();
    std::string verdict = "too few steps to compare them";
    if (choice.rounds() > 0)
      verdict = std::string(choice.decidedByShortfalls()
                                ? "fewer solves short of the tolerance in the last round: "
                                : "faster in the last round: ") +
                toString(choice.preferred());
    std::printf("  auto: multigrid solved %ld of %d steps, cg the rest; %s\n", multigridSteps,
                a.steps, verdict.c_str());
  }
  std::printf(
      "  final energy: kinetic %.4g, elastic %.4g, gravitational %.4g J (from the rest shape)\n",
      e.kinetic, e.elastic, e.gravitational);
  if (!sim.fixedNodes().empty())
    std::printf("  supports: reaction %s N in all at the end, on the %zu fixed nodes\n",
                commaSeparated(sim.supportReaction(sim.state())).c_str(), sim.fixedNodes().size());
  std::printf("wrote %s (%lld frame%s)\n", recorder.path().c_str(),
              static_cast<long long>(recorder.frames()), recorder.frames() == 1 ? "" : "s");
  if (!a.log.empty()) {
    writeStepLog(a.log, log);
    std::printf("wrote %s (%d step%s and the start)\n", a.log.c_str(), a.steps,
                a.steps == 1 ? "" : "s");
  }
  if (const SolveShortfall shortfall = sim.solveShortfall(); shortfall.steps > 0)
    std::fprintf(stderr, "warning: %s\n",
                 describe(shortfall, options, "--solver multigrid").c_str());
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run the corotated FEM on a dataset level; writes a ParaView time series (.pvd)");
  cmd->add_option("DATASET", a->dataset, kDatasetHelp)->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "time series RUN.pvd (frames go to RUN_frames/)")
      ->required();
  cmd->add_option("--steps", a->steps, "time steps")->capture_default_str()->check(wholeNumber(0));
  addTimeStepOption(*cmd, a->options.timeStep);
  cmd->add_option("--every", a->every, "write every k-th step (and the last)")
      ->capture_default_str()
      ->check(wholeNumber(1));
  addScenarioOptions(*cmd, a->scenario);
  cmd->add_option("--level", a->level, kLevelHelp)->check(anyWholeNumber());
  cmd->add_option("--initial", a->initial,
                  "start from a frame a run of this level wrote (RUN_frames/control_N.vtu): its "
                  "positions and velocities replace the scenario's start; time starts at 0")
      ->check(CLI::ExistingFile);
  cmd->add_option("--solver", a->solver,
                  "cg (block-Jacobi CG), multigrid (CG with a V-cycle) or auto (whichever of "
                  "the two is faster here, timed every 120 steps)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "cg", "multigrid"}));
  cmd->add_option("--tangent", a->tangent,
                  "the implicit step's stiffness: full (R K R^T and the rotation term: steady "
                  "under large steps on stretched bodies) or warped (R K R^T alone, stiffness "
                  "warping: a cheaper element pass)")
      ->capture_default_str()
      ->check(CLI::IsMember({"full", "warped"}));
  cmd->add_option("--tolerance", a->options.tolerance, "relative residual of each solve")
      ->capture_default_str()
      ->check(positiveNumber());
  cmd->add_option("--guess-solutions", a->options.guessSolutions,
                  "start each solve from the best combination of the last N solutions "
                  "(0: from the last one as it is)")
      ->capture_default_str()
      ->check(wholeNumber(0, kMaxProductColumns));
  cmd->add_option("--coarse-reuse", a->options.coarseReuse,
                  "multigrid: rebuild the coarse operators every N steps (solves stay exact)")
      ->capture_default_str()
      ->check(wholeNumber(1));
  cmd->add_option("--coarse-operators", a->coarseOperators,
                  "multigrid: galerkin (P^T A P) or rediscretized (each coarse mesh's own FEM)")
      ->capture_default_str()
      ->check(CLI::IsMember({"galerkin", "rediscretized"}));
  addMaterialOptions(*cmd, a->material);
  cmd->add_option("--surface", a->surface,
                  "also write this surface, bound (closest) and deformed, per frame; a binding "
                  "from bind is used as it is, on its level")
      ->check(CLI::ExistingFile);
  cmd->add_option("--log", a->log,
                  "also write every step to this table (.csv): time, solver, iterations, "
                  "residual, floor contacts, the step's times by stage, kinetic, elastic and "
                  "gravitational energy")
      ->check(fileEnding(".csv"));
  cmd->add_flag("-q,--quiet", a->quiet, "no progress on stderr");
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
