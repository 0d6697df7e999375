// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <utility>

#include "BodyContact.h"
#include "BodyModels.h"
#include "ContactCoefficients.h"
#include "NodeConstraints.h"
#include "NodeNumbering.h"
#include "ObstacleContact.h"
#include "SolverStack.h"
#include "SurfaceLoadForce.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/deformation/SurfaceDeformer.h"

namespace tetskin {

SimulationOptions uprightAlong(UpAxis up, SimulationOptions options) {
  options.up = up;
  options.gravity.setZero();  // (not -9.81 times the unit vector: no -0 printed)
  options.gravity[axisIndex(up)] = -kStandardGravity;
  return options;
}

namespace {

// How often a step is solved again with the skin contacts as its solve
// left them (BodyContact::updateActiveSet), at most. The contacts still to
// change after the last round are left as they are for this step (those
// that end it pulling start the next one out of it). On three
// finest-level bunnies piled in a bowl each round let go about half as
// many as the one before (754, 360, 153) at 50 to 60 CG iterations each.
// One round left so many pulling springs in the step (holding vertices
// behind a skin in it) that such a pile sank into itself with springs
// 1.25 times the default, where three rounds held it.
constexpr int kActiveSetRounds = 3;

// What is wrong with the first node (in `x`'s order) whose new position or
// velocity is not finite or lies beyond kMaxCoordinate, named by its
// number in the level (`outsideNode`): "node 12 would get ..."; empty when
// every node is fine. Beyond that bound the readers refuse a frame (and
// energies overflow), so a state there is a blown-up step, not one to
// write. (One vectorized pass over both vectors when all is well; NaN
// fails the comparison.)
std::string firstBlownUpNode(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                             const std::vector<int>& outsideNode) {
  auto within = [](const Eigen::VectorXd& values) {
    return (values.array().abs() <= kMaxCoordinate).all();
  };
  if (within(x) && within(v)) return {};
  for (Index node = 0; node < x.size() / 3; ++node) {
    for (const auto& [values, what, unit] :
         {std::tuple{&x, "position", " m"}, std::tuple{&v, "velocity", " m/s"}}) {
      const Eigen::Vector3d value = values->segment<3>(3 * node);
      if (within(value)) continue;
      const std::string name =
          "node " + std::to_string(outsideNode[static_cast<std::size_t>(node)]);
      if (!value.allFinite()) return name + " would get a non-finite " + what;
      return name + " would get a " + what + " component of " +
             formatNumber(value.cwiseAbs().maxCoeff()) + unit + ", beyond " +
             formatNumber(kMaxCoordinate) + unit;
    }
  }
  return {};
}

// Throws Error naming the first option out of its range (NaN included);
// the material is CorotatedFem's to check.
void validateOptions(const SimulationOptions& o) {
  using namespace simulation_option;
  for (const auto& [option, value] :
       {std::pair{&kTimeStep, o.timeStep}, std::pair{&kTolerance, o.tolerance},
        std::pair{&kGuessSolutions, static_cast<double>(o.guessSolutions)},
        std::pair{&kCoarseReuse, static_cast<double>(o.coarseReuse)},
        std::pair{&kMaxIterations, static_cast<double>(o.maxIterations)},
        std::pair{&kFriction, o.friction}, std::pair{&kFloorStiffness, o.floorStiffness}})
    if (const auto problem = option->problem(value)) throw Error(*problem);
  if (!o.gravity.allFinite()) throw Error("gravity must be finite");
  if (o.solver != SolverKind::ConjugateGradient &&
      o.coarseOperators == CoarseOperators::Rediscretized &&
      o.coarseLevels != CoarseLevels::Dataset)
    throw Error(
        "rediscretized coarse operators need the dataset's coarse levels (coarse levels "
        "\"dataset\"): the solver's grid levels are no body meshes with an FEM of their own");
  for (const Obstacle& obstacle : o.obstacles)
    if (const auto problem = obstacleProblem(obstacle)) throw Error(*problem);
  for (std::size_t r = 0; r < o.materialRegions.size(); ++r) {
    const ElasticMaterial& m = o.materialRegions[r].material;
    if (m.massDamping != o.material.massDamping ||
        m.stiffnessDamping != o.material.stiffnessDamping)
      throw Error("material region " + std::to_string(r) + ": its damping (" +
                  formatNumber(m.massDamping) + ", " + formatNumber(m.stiffnessDamping) +
                  ") is not the run's (" + formatNumber(o.material.massDamping) + ", " +
                  formatNumber(o.material.stiffnessDamping) +
                  "): a run damps all its elements alike");
  }
  const SkinCollisions& skins = o.skinCollisions;
  if (!(skins.thickness >= 0) || !std::isfinite(skins.thickness))
    throw Error("the skins' contact thickness must be finite and >= 0 (0: automatic), got " +
                formatNumber(skins.thickness));
  if (const auto problem =
          contactCoefficientProblem(skins.staticFriction, skins.kineticFriction, skins.stiffness))
    throw Error("the skins' contact: " + *problem);
  if (o.floorHeight && !std::isfinite(*o.floorHeight))
    throw Error("the floor height must be finite, got " + formatNumber(*o.floorHeight));
}

// Takes `model` (one of `models`, or null) out of the list and forgets it:
// a model a setter replaces (the skins' contact, the surface loads).
template <class Model>
void removeModel(std::vector<std::unique_ptr<ForceModel>>& models, Model*& model) {
  if (!model) return;
  models.erase(
      std::find_if(models.begin(), models.end(), [&](const auto& m) { return m.get() == model; }));
  model = nullptr;
}

// The sum of the force models' forces at `state` (those of contacts only,
// if `contactsOnly`), in the internal numbering.
Eigen::VectorXd forcesAt(const std::vector<std::unique_ptr<ForceModel>>& models,
                         const NodeNumbering& numbering, const SimulationState& state,
                         bool contactsOnly) {
  return sumOfForces(models, numbering.toInternal(state.positions),
                     numbering.toInternal(state.velocities), contactsOnly);
}

}  // namespace

Eigen::VectorXd Simulation::nodeMasses() const {
  Eigen::VectorXd masses(rest_.nodeCount());
  for (Index i = 0; i < numbering_->nodeCount(); ++i)
    masses[numbering_->outside(i)] = fem_.lumpedMass()[3 * i];
  return masses;
}

Simulation::Simulation(const MultiLevelTetMesh& dataset, int level,
                       const SimulationOptions& options, const std::string& datasetName)
    : level_(level < 0 ? dataset.finestLevel() : level),
      levelFirstNode_(dataset.levels.at(static_cast<std::size_t>(level_)).firstNode),
      rest_(extractLevel(dataset, level_)),
      options_(options),
      numbering_(std::make_unique<NodeNumbering>(rest_, levelName(datasetName, level_))),
      internal_(numbering_->renumbered(rest_)),
      fem_(internal_, options.material, options.materialRegions) {
  validateOptions(options);
  BodyModels body = bodyModels(fem_, options);
  models_ = std::move(body.models);
  constraints_ = body.constraints;
  obstacles_ = body.obstacles;
  integrator_ = std::make_unique<ImplicitEuler>(options.timeStep, fem_.lumpedMass());
  solvers_ = std::make_unique<SolverStack>(dataset, level_, internal_, options,
                                           integrator_->coarseDiscretization(models_), datasetName);
  x_ = fem_.restPositions();
  v_.setZero(fem_.dofCount());
  acceleration_.setZero(fem_.dofCount());
  external_.setZero(fem_.dofCount());
  appliedExternal_.setZero(fem_.dofCount());
  dv_.setZero(fem_.dofCount());
  system_ = fem_.pattern();
}

Simulation::~Simulation() = default;

const SolverChoice* Simulation::solverChoice() const {
  return solvers_->choice();
}

void Simulation::setContactSkin(const SurfaceMesh& restSkin, const SurfaceBinding& binding,
                                const std::vector<int>& vertexBodies) {
  if (binding.level != level_)
    throw Error("the contact skin is bound to level " + std::to_string(binding.level) +
                ", the simulation runs level " + std::to_string(level_));
  validateBinding(binding, restSkin.vertexCount(), levelFirstNode_ + rest_.nodeCount(),
                  "the contact skin's binding");
  // The binding in the stepper's own node numbers, for a deformer that
  // reads the step's positions as they are.
  SurfaceBinding internal = binding;
  for (Index v = 0; v < binding.vertexCount(); ++v)
    for (int j = 0; j < binding.controlsPerVertex(); ++j) {
      const Index node = binding.controlIds(v, j) - levelFirstNode_;
      if (node < 0)
        throw Error("the contact skin's binding: vertex " + std::to_string(v) +
                    " is bound to node " + std::to_string(binding.controlIds(v, j)) +
                    ", which is not of level " + std::to_string(level_));
      internal.controlIds(v, j) = numbering_->internal(static_cast<int>(node));
    }
  const Points3 rest = Eigen::Map<const Points3>(fem_.restPositions().data(), fem_.nodeCount(), 3);
  if (obstacles_)
    obstacles_->setSkin(std::make_unique<SurfaceDeformer>(restSkin, internal, rest), internal,
                        options_.contactPoints);
  // The skins against each other and themselves: a model of its own,
  // replaced by a new skin.
  std::vector<int> bodies = vertexBodies;
  if (bodies.empty()) bodies.assign(static_cast<std::size_t>(restSkin.vertexCount()), 0);
  if (static_cast<Index>(bodies.size()) != restSkin.vertexCount())
    throw Error("the contact skin has " + std::to_string(restSkin.vertexCount()) +
                " vertices, its bodies " + std::to_string(bodies.size()));
  if (std::any_of(bodies.begin(), bodies.end(), [](int body) { return body < 0; }))
    throw Error("the contact skin's bodies are numbered from 0");
  for (Index t = 0; t < restSkin.triangleCount(); ++t) {
    const auto bodyOf = [&](int k) {
      return bodies[static_cast<std::size_t>(restSkin.triangles(t, k))];
    };
    if (bodyOf(1) != bodyOf(0) || bodyOf(2) != bodyOf(0))
      throw Error("the contact skin's triangle " + std::to_string(t) +
                  " joins vertices of different bodies");
  }
  removeModel(models_, bodyContact_);
  const bool several =
      std::adjacent_find(bodies.begin(), bodies.end(), std::not_equal_to<>()) != bodies.end();
  const SkinCollisions& settings = options_.skinCollisions;
  if (!several && !settings.self && settings.selfBodies.empty()) return;
  double thickness = settings.thickness;
  if (thickness == 0) thickness = meanEdgeLength(restSkin);
  double stiffness = settings.stiffness;
  if (stiffness == 0)
    stiffness = BodyContact::automaticStiffness(fem_.lumpedMass(), internal, options_.timeStep);
  auto model = std::make_unique<BodyContact>(
      std::make_unique<SurfaceDeformer>(restSkin, internal, rest), restSkin, internal,
      std::move(bodies), fem_.lumpedMass(), *constraints_, settings, thickness, stiffness);
  bodyContact_ = model.get();
  models_.push_back(std::move(model));
}

double Simulation::skinStiffness() const {
  return bodyContact_ ? bodyContact_->stiffness() : 0.0;
}

double Simulation::skinThickness() const {
  return bodyContact_ ? bodyContact_->thickness() : 0.0;
}

SkinContact Simulation::skinContact(const SimulationState& state) const {
  SkinContact out;
  if (obstacles_)
    obstacles_->skinContact(numbering_->toInternal(state.positions), state.time, out.penetration,
                            out.forces);
  return out;
}

void Simulation::setObstaclePlacement(std::size_t k, const ObstaclePose& placement) {
  if (k >= options_.obstacles.size())
    throw Error("there is no obstacle " + std::to_string(k) + " (the run has " +
                std::to_string(options_.obstacles.size()) + ")");
  options_.obstacles[k] = placedAt(options_.obstacles[k], placement);
  obstacles_->setPlacement(k, placement);
}

void Simulation::setFixedNodes(const std::vector<int>& nodes) {
  for (int v : nodes)
    if (v < 0 || v >= rest_.nodeCount())
      throw Error("fixed node " + std::to_string(v) + " does not exist");
  fixedNodes_ = nodes;
  applyHolds();
}

void Simulation::setHeldAxes(const std::vector<int>& nodes,
                             const std::vector<std::array<bool, 3>>& axes) {
  if (nodes.size() != axes.size())
    throw Error("held axes: " + std::to_string(nodes.size()) + " nodes, " +
                std::to_string(axes.size()) + " sets of axes");
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i] < 0 || nodes[i] >= rest_.nodeCount())
      throw Error("held node " + std::to_string(nodes[i]) + " does not exist");
    if (!axes[i][0] && !axes[i][1] && !axes[i][2])
      throw Error("held node " + std::to_string(nodes[i]) + " is held along no axis");
  }
  if (!nodes.empty() && bodyContact_)
    throw Error(
        "nodes held along some axes only and skins that meet each other do not go together yet "
        "(the skins' coupling springs hold whole nodes)");
  axisNodes_ = nodes;
  axes_ = axes;
  applyHolds();
}

void Simulation::applyHolds() {
  std::vector<char> dofs(3 * static_cast<std::size_t>(rest_.nodeCount()), 0);
  const auto hold = [&](int node, std::size_t axis) {
    dofs[3 * static_cast<std::size_t>(numbering_->internal(node)) + axis] = 1;
  };
  for (int v : fixedNodes_)
    for (std::size_t k = 0; k < 3; ++k) hold(v, k);
  for (std::size_t i = 0; i < axisNodes_.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (axes_[i][k]) hold(axisNodes_[i], k);
  constraints_->setFixedDofs(std::move(dofs));
  solvers_->setFixedNodes(constraints_->wholeNodes());
}

RunConditions Simulation::conditions() const {
  std::vector<int> prescribed = fixedNodes_;
  prescribed.insert(prescribed.end(), axisNodes_.begin(), axisNodes_.end());
  std::sort(prescribed.begin(), prescribed.end());
  prescribed.erase(std::unique(prescribed.begin(), prescribed.end()), prescribed.end());
  return {options_.floor(), prescribed};
}

void Simulation::setKinematicTargets(const std::vector<int>& nodes, const Points3& targets) {
  if (static_cast<Index>(nodes.size()) != targets.rows())
    throw Error("one target per kinematic node");
  std::vector<int> internal;
  for (int v : nodes) {
    if (v < 0 || v >= rest_.nodeCount() || !constraints_->isFixed(numbering_->internal(v)))
      throw Error("kinematic node " + std::to_string(v) + " must be a fixed node");
    internal.push_back(numbering_->internal(v));
  }
  constraints_->setTargets(std::move(internal), targets);
}

void Simulation::setExternalForces(const Points3& forces) {
  requireRows("external forces", forces.rows(), rest_.nodeCount(), "nodes");
  for (Index v = 0; v < forces.rows(); ++v)
    if (!forces.row(v).allFinite())
      throw Error("external forces: node " + std::to_string(v) + "'s force is not finite");
  std::lock_guard lock(mutex_);
  external_ = numbering_->toInternal(forces);
}

Points3 Simulation::externalForces() const {
  std::lock_guard lock(mutex_);
  return numbering_->toOutside(external_);
}

void Simulation::setPositions(const Points3& positions) {
  requireRows("positions", positions.rows(), rest_.nodeCount(), "nodes");
  std::lock_guard lock(mutex_);
  x_ = numbering_->toInternal(positions);
  acceleration_.setZero();  // (a new start, not the outcome of a step)
}

void Simulation::setVelocities(const Points3& velocities) {
  requireRows("velocities", velocities.rows(), rest_.nodeCount(), "nodes");
  std::lock_guard lock(mutex_);
  v_ = numbering_->toInternal(velocities);
  acceleration_.setZero();
}

StepStats Simulation::step() {
  StepStats stats;
  const double h = options_.timeStep;
  {
    std::lock_guard lock(mutex_);
    stepExternal_ = external_;
  }
  // The system of the step: the force models' sum, with the fixed and
  // driven nodes' rows.
  const auto start = std::chrono::steady_clock::now();
  stats.contacts = integrator_->assemble(models_, time_, x_, v_, stepExternal_, system_, rhs_);
  stats.assemblySeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SolveStats solve = solvers_->solve(system_, rhs_, dv_, steps_,
                                     {&x_, integrator_->springs(), integrator_->coupling()}, stats);
  // The skins' springs push, never pull: those that would end the step
  // pulling leave it, those out of it that would end it pushing come in
  // (and so do vertices whose path over the first solve's step crosses a
  // skin: later rounds mostly let contacts go), and it is solved again. Their share leaves or joins
  // the assembled system; only one on a held node has the step assembled anew.
  for (int round = 0; round < kActiveSetRounds && bodyContact_; ++round) {
    const auto restart = std::chrono::steady_clock::now();
    const BodyContact::ActiveSetChange change =
        bodyContact_->updateActiveSet(x_, v_, dv_, integrator_->stepSystem(), round == 0);
    if (!change.any()) break;
    if (change.reassemble)
      stats.contacts = integrator_->assemble(models_, time_, x_, v_, stepExternal_, system_, rhs_);
    else
      stats.contacts += change.taken - change.released;
    stats.assemblySeconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - restart).count();
    // (From the last solve's answer: the system changed by a few springs.)
    solve = solvers_->resolve(stats.solver, system_, rhs_, dv_, steps_,
                              {&x_, integrator_->springs(), integrator_->coupling()}, stats);
  }
  Eigen::VectorXd x, v;
  integrator_->advance(models_, x_, v_, dv_, x, v);
  // The state stays the last one that was fine. (A solve that overflowed
  // spreads NaN over every node through CG's dot products: no node to name.)
  const std::string problem = dv_.allFinite()
                                  ? firstBlownUpNode(x, v, numbering_->order())
                                  : std::string("the solver's velocity update is not finite");
  if (!problem.empty())
    throw Error("the simulation diverged in step " + std::to_string(steps_ + 1) +
                " (t = " + formatNumber(time_ + h) + " s): " + problem +
                "; smaller loads or time steps, or a stiffer material, may keep it stable");
  solvers_->remember(dv_);
  std::lock_guard lock(mutex_);
  if (solve.relativeResidual > options_.tolerance) {
    ++shortfall_.steps;
    if (solve.relativeResidual > shortfall_.largestResidual) {
      shortfall_.largestResidual = solve.relativeResidual;
      shortfall_.largestAtStep = steps_ + 1;
    }
  }
  acceleration_ = (v - v_) / h;
  x_ = std::move(x);
  v_ = std::move(v);
  appliedExternal_.swap(stepExternal_);
  time_ += h;
  ++steps_;
  return stats;
}

SimulationState Simulation::state() const {
  std::lock_guard lock(mutex_);
  const NodeNumbering& n = *numbering_;
  return {
      n.toOutside(x_), n.toOutside(v_), n.toOutside(appliedExternal_), n.toOutside(acceleration_),
      time_,           steps_};
}

double Simulation::time() const {
  std::lock_guard lock(mutex_);
  return time_;
}

Index Simulation::steps() const {
  std::lock_guard lock(mutex_);
  return steps_;
}

SolveShortfall Simulation::solveShortfall() const {
  std::lock_guard lock(mutex_);
  return shortfall_;
}

std::string describe(const SolveShortfall& shortfall, const SimulationOptions& options,
                     const std::string& multigrid) {
  return std::to_string(shortfall.steps) + (shortfall.steps == 1 ? " step" : " steps") +
         " stopped at the iteration limit (" + std::to_string(options.maxIterations) +
         ") with the relative residual above the tolerance " + formatNumber(options.tolerance) +
         " (at most " + formatNumber(shortfall.largestResidual) + ", in step " +
         std::to_string(shortfall.largestAtStep) + ")" +
         (options.solver == SolverKind::Multigrid
              ? ""
              : "; " + multigrid + " needs far fewer iterations on stiff bodies");
}

Energies Simulation::energies() const {
  Eigen::VectorXd x, v;
  {
    std::lock_guard lock(mutex_);
    x = x_;
    v = v_;
  }
  Energies e;
  e.kinetic = 0.5 * v.dot(fem_.lumpedMass().cwiseProduct(v));
  for (const auto& model : models_) model->addEnergy(x, e);
  return e;
}

Points3 Simulation::reactionForces(const SimulationState& state) const {
  Points3 reactions = Points3::Zero(rest_.nodeCount(), 3);
  if (fixedNodes_.empty() && axisNodes_.empty()) return reactions;
  // What holds a node: its inertia less every force model's force and
  // the loads.
  const Eigen::VectorXd force = forcesAt(models_, *numbering_, state, false);
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  const auto reaction = [&](int node) -> Eigen::RowVector3d {
    const Index i = 3 * numbering_->internal(node);
    const Eigen::Vector3d inertia =
        mass.segment<3>(i).cwiseProduct(state.accelerations.row(node).transpose());
    return inertia.transpose() - force.segment<3>(i).transpose() - state.externalForces.row(node);
  };
  // (A node held along some axes: its reaction along those; along the
  // others nothing holds it.)
  for (std::size_t k = 0; k < axisNodes_.size(); ++k) {
    const Eigen::RowVector3d r = reaction(axisNodes_[k]);
    for (int axis = 0; axis < 3; ++axis)
      if (axes_[k][static_cast<std::size_t>(axis)]) reactions(axisNodes_[k], axis) = r[axis];
  }
  for (int node : fixedNodes_) reactions.row(node) = reaction(node);
  return reactions;
}

void Simulation::setSurfaceLoads(const std::vector<SurfaceLoad>& loads) {
  std::vector<SurfaceLoad> internal = loads;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (const auto problem = surfaceLoadProblem(loads[k], rest_.nodeCount()))
      throw Error("surface load " + std::to_string(k) + ": " + *problem);
    for (Index f = 0; f < loads[k].faces.rows(); ++f)
      for (int c = 0; c < 3; ++c)
        internal[k].faces(f, c) = numbering_->internal(loads[k].faces(f, c));
  }
  const double factor = surfaceLoadForce_ ? surfaceLoadForce_->factor() : 1.0;
  removeModel(models_, surfaceLoadForce_);
  if (loads.empty()) return;
  auto model = std::make_unique<SurfaceLoadForce>(std::move(internal), fem_.restPositions());
  model->setFactor(factor);
  surfaceLoadForce_ = model.get();
  models_.push_back(std::move(model));
}

void Simulation::setSurfaceLoadFactor(double factor) {
  if (!std::isfinite(factor))
    throw Error("the surface loads' factor must be finite, got " + formatNumber(factor));
  if (surfaceLoadForce_) surfaceLoadForce_->setFactor(factor);
}

Points3 Simulation::surfaceLoadForces(const SimulationState& state) const {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(fem_.dofCount());
  if (surfaceLoadForce_)
    surfaceLoadForce_->addForceAt(numbering_->toInternal(state.positions),
                                  numbering_->toInternal(state.velocities), force);
  return numbering_->toOutside(force);
}

Points3 Simulation::contactForces(const SimulationState& state) const {
  return numbering_->toOutside(forcesAt(models_, *numbering_, state, true));
}

Eigen::Vector3d Simulation::supportReaction(const SimulationState& state) const {
  return reactionForces(state).colwise().sum().transpose();
}

FrameFields Simulation::frameFields(const SimulationState& state) const {
  CorotatedFem::ElementMeasures measures =
      fem_.elementMeasures(numbering_->toInternal(state.positions));
  // (The surface loads' nodal forces are external forces as the loads on
  // nodes are.)
  return {state.positions,
          state.velocities,
          surfaceLoadForce_ ? Points3(state.externalForces + surfaceLoadForces(state))
                            : state.externalForces,
          reactionForces(state),
          std::move(measures.vonMisesStress),
          std::move(measures.equivalentStrain),
          obstacles_ || bodyContact_ ? contactForces(state) : Points3(),
          std::move(measures.stress)};
}

}  // namespace tetskin
