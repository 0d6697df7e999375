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
#include "OptionChecks.h"
#include "Progress.h"
#include "RunOptions.h"
#include "SceneFlags.h"
#include "SurfaceInput.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/StepLogFile.h"
#include "tetskin/session/RunSpecJson.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::cli {
namespace {

struct SimulateArgs {
  std::filesystem::path dataset, output, surface, initial, log;
  int steps = static_cast<int>(recording_option::kSteps.defaultValue), level = kFinestLevel,
      every = static_cast<int>(recording_option::kEvery.defaultValue),
      pieces = static_cast<int>(kPiecesOption.defaultValue);
  RunArgs run;
  bool quiet = false, printRun = false;
  bool staticOnly = false;  // --static
  // --initial equilibrium (or --static): start from the static equilibrium
  bool equilibrium() const { return staticOnly || initial == kEquilibrium; }
  static constexpr const char* kEquilibrium = "equilibrium";
};

// (Checked before any work, as a typo would be.)
void checkOptions(const SimulateArgs& a, const CLI::App& cmd) {
  checkRunOptions(a.run, cmd);
  requireOutputOrPrintRun(a.output, a.printRun);
  if (a.pieces > 1 && a.surface.empty())
    throw Error(std::string(kPiecesOption.flag) + " " + std::to_string(a.pieces) +
                " splits the surface's frames: give the surface (--surface)");
  if (!a.log.empty()) {
    requireNotAnInput(a.log, {a.dataset, a.surface, a.initial, a.output});
    requireWritableLocation(a.log);  // before the run, not after it
  }
  if (a.staticOnly && !a.initial.empty() && a.initial != SimulateArgs::kEquilibrium)
    throw Error(
        "--static solves for the equilibrium from the scenario's start: it takes no "
        "--initial frame");
  if (a.staticOnly && givenName(cmd, recording_option::kSteps))
    throw Error("--static writes the equilibrium alone: it takes no --steps");
  if (!a.initial.empty() && !a.equilibrium()) {
    if (!std::filesystem::is_regular_file(a.initial))
      throw Error(a.initial.string(), 0,
                  "no such frame (--initial takes a frame file or "
                  "\"equilibrium\")");
    // The frame replaces the scenario's start; its folder is not the one
    // this run writes, where frame 0 would overwrite it.
    std::error_code error;
    if (std::filesystem::equivalent(a.initial.parent_path().empty() ? "." : a.initial.parent_path(),
                                    RunRecorder::framesDirectory(a.output), error))
      throw Error(a.initial.string(), 0,
                  "is among the frames this run writes (-o " + a.output.string() +
                      "): write the new run to another name");
  }
}

struct RunTotals {
  double stepSeconds = 0;
  long iterations = 0, multigridSteps = 0;
  int contacts = 0;  // of the last step
};

// What the run was and how it ended, on stdout.
void report(const SimulateArgs& a, const SimulationSession& session, const RunSpec& spec,
            const RunTotals& totals) {
  const Simulation& sim = session.simulation();
  const SimulationOptions& options = session.options();
  const ScenarioParameters& parameters = spec.parameters;
  const Energies e = sim.energies();
  // The multigrid's coarse operators and levels, where it may run.
  const std::string multigrid = options.solver == SolverKind::ConjugateGradient
                                    ? ""
                                    : std::string(", ") + toString(options.coarseOperators) +
                                          " on " + toString(options.coarseLevels);
  std::printf(
      "simulated %d steps of %g s on level %d (%lld tetrahedra), scenario %s, solver %s%s, "
      "%s tangent\n",
      a.steps, options.timeStep, session.level(),
      static_cast<long long>(sim.restMesh().elementCount()), session.scenario().name(),
      toString(options.solver), multigrid.c_str(), toString(options.tangent));
  if (!a.initial.empty()) std::printf("  started from %s\n", a.initial.c_str());
  if (session.bodies().empty()) std::printf("  material: %s\n", describe(options.material).c_str());
  for (const RunBody& body : session.bodies())
    std::printf("  body %s: %lld tetrahedra, %lld skin vertices, material %s\n", body.name.c_str(),
                static_cast<long long>(body.range.elementCount),
                static_cast<long long>(body.range.vertexCount), describe(body.material).c_str());
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
  if (!parameters.surfaceLoads.empty()) {
    // (At rest: the pressure's total changes as the faces deform.)
    const Eigen::VectorXd rest = sim.restMesh().nodes.reshaped<Eigen::RowMajor>();
    for (std::size_t k = 0; k < parameters.surfaceLoads.size(); ++k) {
      const SurfaceLoad& load = parameters.surfaceLoads[k];
      Eigen::VectorXd forces = Eigen::VectorXd::Zero(rest.size());
      addSurfaceLoadForces(load, rest, rest, 1.0, forces);
      std::printf(
          "  surface load %zu: pressure %s Pa, traction %s Pa on %lld faces of %s m^2 "
          "(total force at rest %s N)\n",
          k, formatNumber(load.pressure).c_str(), commaSeparated(load.traction).c_str(),
          static_cast<long long>(load.faces.rows()), formatNumber(loadedArea(load, rest)).c_str(),
          commaSeparated(forces.reshaped(3, rest.size() / 3).rowwise().sum()).c_str());
    }
  }
  if (options.hasContact()) {
    const Eigen::RowVector3d force = sim.contactForces(sim.state()).colwise().sum();
    const std::size_t count = options.obstacles.size();
    const std::string met =
        (options.floorHeight ? std::string("the floor") + (count > 0 ? " and " : "") : "") +
        (count > 0 ? std::to_string(count) + " obstacle" + (count == 1 ? "" : "s") : "");
    std::printf("  %s met by the %s; at the end %d contacts, contact force %s N\n", met.c_str(),
                session.hasSurface() && options.contactPoints != ContactPoints::Cage
                    ? (options.contactPoints == ContactPoints::Both ? "skin and nodes" : "skin")
                    : "nodes",
                totals.contacts, commaSeparated(force.transpose()).c_str());
  }
  if (const double thickness = sim.skinThickness(); thickness > 0) {
    const std::size_t bodies = session.bodies().size();
    const std::string meets =
        bodies > 1 ? "the " + std::to_string(bodies) + " bodies' skins meet each other" +
                         (options.skinCollisions.selfBodies.empty() ? "" : " and themselves")
                   : std::string("the skin meets itself");
    std::printf("  %s: a shell %s thick, springs of %s N/m; at the end %d contacts in all\n",
                meets.c_str(), formatNumber(thickness).c_str(),
                formatNumber(sim.skinStiffness()).c_str(), totals.contacts);
  }
  if (a.steps > 0)
    std::printf("  %.1f steps/s, %.1f solver iterations per step\n",
                a.steps / std::max(totals.stepSeconds, 1e-12),
                static_cast<double>(totals.iterations) / a.steps);
  if (options.solver == SolverKind::Automatic && a.steps > 0) {
    const SolverChoice& choice = *sim.solverChoice();
    std::printf(
        "  auto: multigrid solved %ld of %d steps, cg the rest; %d sample steps of the other "
        "solver (%d cut off at their budget), %d changes; preferred at the end: %s%s\n",
        totals.multigridSteps, a.steps, choice.samples(), choice.cutOffSamples(), choice.switches(),
        toString(choice.preferred()),
        choice.switches() > 0 && choice.decidedByShortfalls()
            ? " (the other stopped short of the tolerance)"
            : "");
  }
  std::printf(
      "  final energy: kinetic %.4g, elastic %.4g, gravitational %.4g J (from the rest shape)\n",
      e.kinetic, e.elastic, e.gravitational);
  if (!parameters.surfaceLoads.empty())
    std::printf("  the surface loads' potential: %.4g J\n", e.load);
  if (!sim.fixedNodes().empty())
    std::printf("  supports: reaction %s N in all at the end, on the %zu fixed nodes\n",
                commaSeparated(sim.supportReaction(sim.state())).c_str(), sim.fixedNodes().size());
  const RunRecorder& recorder = *session.recorder();
  std::printf("wrote %s (%lld frame%s)\n", recorder.path().c_str(),
              static_cast<long long>(recorder.frames()), recorder.frames() == 1 ? "" : "s");
  if (!a.log.empty())
    std::printf("wrote %s (%d step%s and the start)\n", a.log.c_str(), a.steps,
                a.steps == 1 ? "" : "s");
}

// What a run starts from: a dataset and the command line's options, or a
// scene (SceneRun.h) with the command line's options over its values.
struct RunInput {
  Dataset dataset;
  std::string datasetName;  // as the binding names it
  RunSpec spec;
  std::optional<std::pair<SurfaceMesh, SurfaceBinding>> surface;
};

RunInput datasetInput(const SimulateArgs& a, const CLI::App& cmd) {
  RunInput in;
  in.dataset = loadDataset(a.dataset);
  in.datasetName = a.dataset.generic_string();
  // A binding from `tetskin bind` follows as it is, on its level.
  std::optional<SurfaceInput> input;
  if (!a.surface.empty()) input = readSurfaceInput(a.surface, in.dataset.mesh);
  const int level =
      input ? commandLevel(*input, in.dataset.mesh, a.level, cmd.count(kLevelOption.flag) > 0)
            : resolveLevel(in.dataset.mesh, a.level);
  in.spec = runSpec(a.run, cmd, in.dataset, level, a.dataset.string());
  if (input) {
    SurfaceBinding binding = bindingAt(*input, in.dataset.mesh, level);
    in.surface.emplace(std::move(input->surface), std::move(binding));
  }
  return in;
}

RunInput sceneInput(SimulateArgs& a, const CLI::App& cmd) {
  SceneRun run = loadSceneWithFlags(
      a.dataset, cmd.count(kLevelOption.flag) > 0 ? std::optional<int>(a.level) : std::nullopt,
      a.surface);
  if (!givenName(cmd, recording_option::kSteps)) a.steps = run.steps;
  applyRunOptions(a.run, cmd,
                  run.dataset.mesh.levels[static_cast<std::size_t>(run.level)].nodeCount,
                  run.request);
  RunInput in;
  in.spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  in.dataset = std::move(run.dataset);
  in.datasetName = std::filesystem::path(run.request.datasetName).generic_string();
  if (run.surface)
    in.surface.emplace(std::move(run.surface->surface), std::move(run.surface->binding));
  return in;
}

void run(SimulateArgs& a, const CLI::App& cmd) {
  checkOptions(a, cmd);
  RunInput in = isSceneFile(a.dataset) ? sceneInput(a, cmd) : datasetInput(a, cmd);
  const Dataset& dataset = in.dataset;
  const RunSpec& spec = in.spec;
  if (a.printRun) {
    std::printf("%s\n", runSpecJson(spec).c_str());
    return;
  }
  SimulationSession session(dataset.mesh, spec);
  if (!a.initial.empty() && !a.equilibrium())
    session.startFromFrame(a.initial);  // (drop's lift too)
  for (const std::string& warning : session.takeWarnings(OptionNames::Flags))
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  // The bound surface, if any, follows every frame (frame 0 too: the
  // scenario's start, not always the rest), and meets the obstacles.
  if (in.surface)
    session.bindSurface(std::move(in.surface->first), std::move(in.surface->second),
                        in.datasetName);
  if (a.equilibrium()) {
    // (With the surface bound: the skin meets the floor and obstacles.)
    const StaticStats stats = session.solveStatic();
    std::printf(
        "static equilibrium: %d Newton iterations (%d linear), largest force left %s N "
        "(largest load %s N)\n",
        stats.iterations, stats.linearIterations, formatNumber(stats.residual).c_str(),
        formatNumber(stats.load).c_str());
    if (!stats.converged)
      std::fprintf(stderr,
                   "warning: the static solve stopped short of its tolerance (%s of the largest "
                   "load); the run starts from the best positions it found\n",
                   formatNumber(kStaticTolerance).c_str());
  }
  if (a.staticOnly) a.steps = 0;
  session.record(a.output, a.pieces);
  // --log: the start and every step, written at the end (and by a run cut
  // short, with the steps before it).
  if (!a.log.empty()) session.keepStepLog();

  Progress progress(a.quiet);
  session.recordFrame();
  RunTotals totals;
  try {
    session.run(a.steps, a.every, [&](int i, const StepStats& stats) {
      totals.stepSeconds += session.lastStepSeconds();
      totals.iterations += stats.iterations;
      totals.multigridSteps += stats.solver == SolverKind::Multigrid;
      totals.contacts = stats.contacts;
      progress.update("simulate", static_cast<std::size_t>(i + 1),
                      static_cast<std::size_t>(a.steps));
    });
  } catch (const Error& e) {  // e.g. diverged: say what the run leaves behind
    std::string kept = std::string(e.what()) + "; " + session.recorder()->path().string() +
                       " keeps the " + std::to_string(session.recorder()->frames()) +
                       " frame(s) written before it";
    if (!a.log.empty()) {
      writeStepLog(a.log, session.stepLog());
      kept += ", " + a.log.string() + " the " + std::to_string(session.simulation().steps()) +
              " step(s)";
    }
    throw Error(kept);
  }
  if (!a.log.empty()) writeStepLog(a.log, session.stepLog());
  report(a, session, spec, totals);
  for (const std::string& warning : session.takeWarnings(OptionNames::Flags))
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run the corotated FEM on a dataset level; writes a ParaView time series (.pvd)");
  addDatasetOrSceneArgument(*cmd, a->dataset,
                            "the body, obstacles, floor and settings, which the options given "
                            "here override");
  cmd->add_option("-o,--output", a->output,
                  "time series RUN.pvd (frames go to RUN_frames/); required unless --print-run");
  addNumberOption(*cmd, recording_option::kSteps, a->steps);
  addNumberOption(*cmd, recording_option::kEvery, a->every);
  cmd->add_option(kLevelOption.flag, a->level, kLevelOption.help)->check(anyWholeNumber());
  cmd->add_option("--initial", a->initial,
                  "start from a frame a run of this level wrote (RUN_frames/control_N.vtu): its "
                  "positions and velocities replace the scenario's start; time starts at 0; or "
                  "\"equilibrium\": from the static equilibrium under the scenario's loads and "
                  "held nodes (Newton's method from the scenario's start)");
  cmd->add_flag("--static", a->staticOnly,
                "solve for the static equilibrium (as --initial equilibrium) and write it as the "
                "run's only frame; prints the Newton iterations and the force left");
  addRunOptions(*cmd, a->run);
  addPrintRunFlag(*cmd, a->printRun);
  cmd->add_option("--surface", a->surface,
                  "also write this surface, bound (closest) and deformed, per frame; a binding "
                  "from bind is used as it is, on its level")
      ->check(CLI::ExistingFile);
  addNumberOption(*cmd, kPiecesOption, a->pieces);
  cmd->add_option("--log", a->log,
                  "also write every step to this table (.csv): time, solver, iterations, "
                  "residual, contacts, the step's times by stage, kinetic, elastic and "
                  "gravitational energy")
      ->check(fileEnding(".csv"));
  cmd->add_flag("-q,--quiet", a->quiet, "no progress on stderr");
  addCompressOption(*cmd);
  cmd->callback([a, cmd] { run(*a, *cmd); });
}

}  // namespace tetskin::cli
