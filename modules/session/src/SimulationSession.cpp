// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SimulationSession.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/session/SkinFields.h"

namespace tetskin {

SimulationSession::SimulationSession(const MultiLevelTetMesh& dataset, const RunSpec& spec)
    : dataset_(dataset), level_(spec.level), datasetName_(spec.datasetName), bodies_(spec.bodies) {
  const TetMesh rest = extractLevel(dataset, spec.level);
  // An unknown scenario fails before the simulation's work.
  scenario_ = makeScenario(spec.scenario, spec.parameters);
  simulation_ = std::make_unique<Simulation>(
      dataset, spec.level, scenarioOptions(spec.scenario, spec.options, rest), spec.datasetName);
  scenario_->setUp(*simulation_);
  if (!spec.initialVelocity.isZero()) {
    const SimulationState start = simulation_->state();
    simulation_->setVelocities(start.velocities.rowwise() + spec.initialVelocity.transpose());
  }
  if (std::any_of(bodies_.begin(), bodies_.end(),
                  [](const RunBody& body) { return !body.velocity.isZero(); })) {
    Points3 velocities = simulation_->state().velocities;
    for (const RunBody& body : bodies_)
      velocities.middleRows(body.range.firstNode, body.range.nodeCount).rowwise() +=
          body.velocity.transpose();
    simulation_->setVelocities(velocities);
  }
}

SimulationSession::~SimulationSession() = default;

void SimulationSession::startFrom(const FrameState& start) {
  simulation_->setPositions(start.positions);
  simulation_->setVelocities(start.velocities);
  startToWarn_ = true;
  // A log kept from the scenario's start begins again at this one.
  if (keepLog_) {
    log_.clear();
    logRow(0, nullptr, 0);
  }
}

void SimulationSession::startFromFrame(const std::filesystem::path& frame) {
  startFrom(readSimulationFrame(frame, simulation_->restMesh(),
                                "level " + std::to_string(level_) + " of " + datasetName_));
}

void SimulationSession::bindSurface(SurfaceMesh surface, SurfaceBinding binding,
                                    std::string dataset) {
  auto bound = std::make_unique<BoundSurface>();
  bound->surface = std::move(surface);
  bound->binding = std::move(binding);
  bound->dataset = std::move(dataset);
  bound->deformed.emplace();
  deformer_ = std::make_unique<SurfaceDeformer>(bound->surface, bound->binding, dataset_.nodes);
  std::vector<int> vertexBodies;
  if (!bodies_.empty()) {
    const BodyRange& last = bodies_.back().range;
    if (bound->surface.vertexCount() != last.firstVertex + last.vertexCount)
      throw Error("the surface has " + std::to_string(bound->surface.vertexCount()) +
                  " vertices, the run's bodies' skins " +
                  std::to_string(last.firstVertex + last.vertexCount));
    vertexBodies.resize(static_cast<std::size_t>(bound->surface.vertexCount()));
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      std::fill_n(vertexBodies.begin() + bodies_[b].range.firstVertex, bodies_[b].range.vertexCount,
                  static_cast<int>(b));
  }
  simulation_->setContactSkin(bound->surface, bound->binding, vertexBodies);
  bound_ = std::move(bound);
  allNodes_ = dataset_.nodes;
}

const BoundSurface& SimulationSession::deformedSurface(const Points3& positions) {
  if (!bound_) throw Error("no surface is bound to the simulation");
  const LevelRange& range = dataset_.levels[static_cast<std::size_t>(level_)];
  allNodes_.middleRows(range.firstNode, range.nodeCount) = positions;
  deformer_->deform(allNodes_, bound_->deformed->positions, bound_->deformed->normals);
  bound_->deformed->scalars.clear();  // (of another state)
  return *bound_;
}

StaticStats SimulationSession::solveStatic() {
  scenario_->beforeStep(*simulation_, simulation_->time());
  return simulation_->solveStatic();
}

StepStats SimulationSession::step(const Points3* extraForces) {
  const auto start = std::chrono::steady_clock::now();
  scenario_->beforeStep(*simulation_, simulation_->time());
  if (extraForces) simulation_->setExternalForces(simulation_->externalForces() + *extraForces);
  const StepStats stats = simulation_->step();
  lastStepSeconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (keepLog_) logRow(simulation_->steps(), &stats, lastStepSeconds_);
  return stats;
}

StepStats SimulationSession::stepRecordingEvery(int every, const Points3* extraForces) {
  const StepStats stats = step(extraForces);
  if (recording() && simulation_->steps() % every == 0) recordFrame();
  return stats;
}

void SimulationSession::run(int steps, int every,
                            const std::function<void(int, const StepStats&)>& afterStep) {
  for (int i = 0; i < steps; ++i) {
    const StepStats stats = step();
    // Every k-th step, and the last one: a run ends with its end state written.
    if (recording() && ((i + 1) % every == 0 || i + 1 == steps)) recordFrame();
    if (afterStep) afterStep(i, stats);
  }
}

std::vector<std::string> SimulationSession::takeWarnings(OptionNames names) {
  std::vector<std::string> warnings;
  if (startToWarn_) {
    startToWarn_ = false;
    if (std::string below = nodesBelowFloor(*simulation_); !below.empty())
      warnings.push_back(std::move(below));
  }
  const SolveShortfall shortfall = simulation_->solveShortfall();
  if (shortfall.steps > shortfallWarnedSteps_) {
    shortfallWarnedSteps_ = shortfall.steps;
    const char* multigrid = names == OptionNames::Flags  ? "--solver multigrid"
                            : names == OptionNames::Keys ? "solver='multigrid'"
                                                         : "the multigrid solver";
    warnings.push_back(describe(shortfall, simulation_->options(), multigrid));
  }
  return warnings;
}

void SimulationSession::keepStepLog() {
  if (keepLog_) return;
  keepLog_ = true;
  logRow(simulation_->steps(), nullptr, 0);
}

void SimulationSession::logRow(Index step, const StepStats* stats, double seconds) {
  StepLogRow row;
  row.step = step;
  row.time = simulation_->time();
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
  const Energies e = simulation_->energies();
  row.kinetic = e.kinetic;
  row.elastic = e.elastic;
  row.gravitational = e.gravitational;
  row.load = e.load;
  row.reaction = simulation_->supportReaction(simulation_->state());
  log_.push_back(row);
}

void SimulationSession::record(const std::filesystem::path& pvd, int surfacePieces) {
  recorder_.reset();  // (its series stays as written)
  recorder_ = std::make_unique<RunRecorder>(pvd, simulation_->conditions(), surfacePieces);
}

void SimulationSession::recordFrame(const std::optional<SimulationState>& state,
                                    const BoundSurface* drawnSurface) {
  if (!recorder_) throw Error("the run is not being recorded");
  const SimulationState s = state ? *state : simulation_->state();
  const FrameFields fields = simulation_->frameFields(s);
  std::vector<PosedSurface> obstacles;
  for (const Obstacle& o : simulation_->options().obstacles)
    obstacles.push_back({&o.shape->surface(), o.poseAt(s.time).affine(), !o.motion.empty()});
  std::vector<BodyRange> bodies;
  for (const RunBody& body : bodies_) bodies.push_back(body.range);
  if (!bound_ && !drawnSurface) {
    recorder_->addFrame(s.time, simulation_->restMesh(), fields, level_, nullptr, obstacles,
                        bodies);
    return;
  }
  // The surface with the stress and strain on its skin: the front end's
  // drawing of it, or the session's own deformation.
  std::optional<BoundSurface> drawn;
  BoundSurface* surface = bound_.get();
  if (drawnSurface)
    surface = &drawn.emplace(*drawnSurface);
  else
    deformedSurface(s.positions);
  if (!surface->deformed)
    surface->deformed.emplace(DeformedState{surface->surface.positions, surface->surface.normals});
  surface->deformed->scalars = surfaceFields(fields, surface->binding);
  surface->deformed->vectors.clear();
  // The contact skin's penetration and forces, on the skin they are of.
  if (bound_ && surface->binding.vertexCount() == bound_->binding.vertexCount()) {
    SkinContact contact = simulation_->skinContact(s);
    if (contact.penetration.size() > 0) {
      surface->deformed->scalars.push_back({arrays::kPenetration, std::move(contact.penetration)});
      surface->deformed->vectors.push_back({arrays::kContactForce, std::move(contact.forces)});
    }
  }
  recorder_->addFrame(s.time, simulation_->restMesh(), fields, level_, surface, obstacles, bodies);
}

std::vector<PointScalars> SimulationSession::surfaceFields(const FrameFields& fields,
                                                           const SurfaceBinding& binding) const {
  return skinFields(simulation_->restMesh(),
                    dataset_.levels[static_cast<std::size_t>(level_)].firstNode, binding,
                    fields.vonMisesStress, fields.equivalentStrain);
}

}  // namespace tetskin
