// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Simulation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <tuple>

#include "DirichletRows.h"
#include "NodeOrder.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/simulation/Prolongation.h"

namespace tetskin {

const char* toString(CoarseOperators kind) {
  return kind == CoarseOperators::Galerkin ? "galerkin" : "rediscretized";
}

SimulationOptions uprightAlong(UpAxis up, SimulationOptions options) {
  options.up = up;
  options.gravity.setZero();  // (not -9.81 times the unit vector: no -0 printed)
  options.gravity[axisIndex(up)] = -kStandardGravity;
  return options;
}

const char* toString(Tangent tangent) {
  return tangent == Tangent::Full ? "full" : "warped";
}

Tangent tangentFromString(const std::string& name) {
  for (Tangent tangent : {Tangent::Full, Tangent::Warped})
    if (name == toString(tangent)) return tangent;
  throw Error("unknown tangent '" + name + "' (full or warped)");
}

// A coarser level of the rediscretized multigrid: its own corotated FEM at
// positions interpolated from the next finer level's.
struct Simulation::CoarseLevel {
  CoarseLevel(TetMesh coarseMesh, const ElasticMaterial& material, const TetMesh& finer)
      : mesh(std::move(coarseMesh)),
        fem(mesh, material),
        positionsFromFiner(nodalProlongation(finer, mesh.nodes)) {}
  TetMesh mesh;
  CorotatedFem fem;
  // Coarse nodes x finer nodes: the coarse nodes located in the finer mesh.
  SparseMatrix positionsFromFiner;
  SparseMatrix restrictionToCoarse;  // P^T of the prolongation from this level
  Eigen::VectorXd x, force, dampedMass, contactDiagonal, diagonal;
  DirichletRows dirichlet;
};

namespace {

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

// The automatic solver's rounds: trial steps of each solver (at least a
// full coarse-reuse period of multigrid steps, so its trials carry their
// share of coarse rebuilds), and steps between rounds (2 s at 60 steps/s).
constexpr int kMinTrialSteps = 3, kMaxTrialSteps = 8, kStepsBetweenTrials = 120;

// Throws Error naming the first option out of its range (NaN included);
// the material is CorotatedFem's to check.
void validateOptions(const SimulationOptions& o) {
  if (!(o.timeStep > 0) || !std::isfinite(o.timeStep))
    throw Error("the time step must be a positive number of seconds, got " +
                formatNumber(o.timeStep));
  if (!o.gravity.allFinite()) throw Error("gravity must be finite");
  if (o.floorHeight && !std::isfinite(*o.floorHeight))
    throw Error("the floor height must be finite, got " + formatNumber(*o.floorHeight));
  if (!(o.floorStiffness >= 0) || !std::isfinite(o.floorStiffness))
    throw Error("the floor stiffness must be >= 0 (0: automatic), got " +
                formatNumber(o.floorStiffness));
  if (!(o.friction >= 0 && o.friction <= 1))
    throw Error("friction must lie in [0, 1], got " + formatNumber(o.friction));
  if (!(o.tolerance > 0 && o.tolerance < 1))
    throw Error("the solver tolerance (a relative residual) must lie in (0, 1), got " +
                formatNumber(o.tolerance));
  if (o.maxIterations < 1)
    throw Error("the solver needs at least 1 iteration, got " + std::to_string(o.maxIterations));
  if (o.coarseReuse < 1)
    throw Error("the coarse-operator reuse must be at least 1 step, got " +
                std::to_string(o.coarseReuse));
}

// The mesh's nodes breadth first along its edges (internal -> mesh id),
// after checking the mesh (`name` says where it is in errors).
std::vector<int> meshNodeOrder(const TetMesh& mesh, const std::string& name) {
  validateTetMesh(mesh, name, /*requirePositiveVolume=*/true);
  const auto n = static_cast<std::size_t>(mesh.nodeCount());
  std::vector<std::vector<int>> neighbours(n);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j)
          neighbours[static_cast<std::size_t>(mesh.elements(e, i))].push_back(mesh.elements(e, j));
  for (std::vector<int>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return breadthFirstOrder(static_cast<int>(n), [&](int v, auto&& visit) {
    for (int u : neighbours[static_cast<std::size_t>(v)]) visit(u);
  });
}

std::vector<int> inverse(const std::vector<int>& order) {
  std::vector<int> rank(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    rank[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
  return rank;
}

TetMesh renumbered(const TetMesh& mesh, const std::vector<int>& order) {
  const std::vector<int> rank = inverse(order);
  TetMesh result;
  result.nodes.resize(mesh.nodeCount(), 3);
  for (Index i = 0; i < mesh.nodeCount(); ++i)
    result.nodes.row(i) = mesh.nodes.row(order[static_cast<std::size_t>(i)]);
  result.elements.resize(mesh.elementCount(), 4);
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      result.elements(e, k) = rank[static_cast<std::size_t>(mesh.elements(e, k))];
  return result;
}

// A level's mesh renumbered breadth first.
TetMesh renumbered(const TetMesh& mesh, const std::string& name) {
  return renumbered(mesh, meshNodeOrder(mesh, name));
}

// Where a level is, for errors: "bunny.json: level 0".
std::string levelName(const std::string& datasetName, int level) {
  const std::string name = "level " + std::to_string(level);
  return datasetName.empty() ? name : datasetName + ": " + name;
}

}  // namespace

Eigen::VectorXd Simulation::toInternal(const Points3& perNode) const {
  Eigen::VectorXd result(3 * perNode.rows());
  for (std::size_t i = 0; i < order_.size(); ++i)
    result.segment<3>(3 * static_cast<Index>(i)) = perNode.row(order_[i]).transpose();
  return result;
}

Points3 Simulation::toOutside(const Eigen::VectorXd& internal) const {
  Points3 result(static_cast<Index>(order_.size()), 3);
  for (std::size_t i = 0; i < order_.size(); ++i)
    result.row(order_[i]) = internal.segment<3>(3 * static_cast<Index>(i)).transpose();
  return result;
}

Eigen::VectorXd Simulation::nodeMasses() const {
  Eigen::VectorXd masses(rest_.nodeCount());
  for (std::size_t i = 0; i < order_.size(); ++i)
    masses[order_[i]] = fem_.lumpedMass()[3 * static_cast<Index>(i)];
  return masses;
}

Simulation::Simulation(const MultiLevelTetMesh& dataset, int level,
                       const SimulationOptions& options, const std::string& datasetName)
    : level_(level < 0 ? dataset.finestLevel() : level),
      rest_(extractLevel(dataset, level_)),
      order_(meshNodeOrder(rest_, levelName(datasetName, level_))),
      rank_(inverse(order_)),
      internal_(renumbered(rest_, order_)),
      options_(options),
      fem_(internal_, options.material),
      guess_(options.guessSolutions) {
  validateOptions(options);
  x_ = fem_.restPositions();
  v_.setZero(fem_.dofCount());
  acceleration_.setZero(fem_.dofCount());
  external_.setZero(fem_.dofCount());
  appliedExternal_.setZero(fem_.dofCount());
  dv_.setZero(fem_.dofCount());
  prescribedDv_.setZero(fem_.dofCount());
  fixedDofs_.assign(static_cast<std::size_t>(fem_.dofCount()), 0);
  system_ = fem_.pattern();
  dampedMass_ = (1 + options.timeStep * options.material.massDamping) * fem_.lumpedMass();
  dirichlet_ = std::make_unique<DirichletRows>();
  if (options.solver != SolverKind::Multigrid) blockJacobi_ = std::make_unique<BlockJacobi>();
  if (options.solver == SolverKind::Automatic)
    choice_.emplace(std::clamp(options.coarseReuse, kMinTrialSteps, kMaxTrialSteps),
                    kStepsBetweenTrials);
  if (options.solver != SolverKind::ConjugateGradient) {
    // This level, then the coarser ones, each renumbered breadth first.
    std::vector<TetMesh> meshes{internal_};
    for (int coarse = level_ - 1; coarse >= 0; --coarse) {
      // (Named as such: a broken coarse level stops the multigrid only.)
      meshes.push_back(renumbered(
          extractLevel(dataset, coarse),
          levelName(datasetName, coarse) + " (a coarser level, used by the multigrid solver)"));
      prolongations_.push_back(nodalProlongation(meshes.back(), meshes[meshes.size() - 2].nodes));
    }
    if (options.coarseOperators == CoarseOperators::Rediscretized) {
      coarse_.reserve(meshes.size() - 1);
      for (std::size_t l = 1; l < meshes.size(); ++l) {
        CoarseLevel& coarseLevel = coarse_.emplace_back(meshes[l], options.material, meshes[l - 1]);
        coarseLevel.dampedMass =
            (1 + options.timeStep * options.material.massDamping) * coarseLevel.fem.lumpedMass();
        coarseLevel.restrictionToCoarse = prolongations_[l - 1].transpose();
        coarseSystems_.push_back(coarseLevel.fem.pattern());
      }
    }
    multigrid_ = std::make_unique<MultigridPreconditioner>(prolongations_);
    multigrid_->setCoarseReuse(options.coarseReuse);
    multigrid_->setSinglePrecision(options.singlePrecisionCycle);
  }
  // Automatic floor stiffness: about a hundred times the stiffest element
  // diagonal, so penetration stays small without ruining the conditioning.
  floorStiffness_ = options.floorStiffness;
  if (options.floorHeight && !(floorStiffness_ > 0)) {
    Eigen::VectorXd force;
    SparseMatrix stiffness = fem_.pattern();
    fem_.update(x_, force, stiffness);
    floorStiffness_ = 100.0 * stiffness.diagonal().maxCoeff();
  }
}

Simulation::~Simulation() = default;

void Simulation::setFixedNodes(const std::vector<int>& nodes) {
  for (int v : nodes)
    if (v < 0 || v >= rest_.nodeCount())
      throw Error("fixed node " + std::to_string(v) + " does not exist");
  fixedNodes_ = nodes;
  std::vector<char> fixedNodes(static_cast<std::size_t>(rest_.nodeCount()), 0);
  for (int v : nodes) fixedNodes[static_cast<std::size_t>(rank_[static_cast<std::size_t>(v)])] = 1;
  auto dofsOf = [](const std::vector<char>& fixed) {
    std::vector<char> dofs(3 * fixed.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i] = fixed[i / 3];
    return dofs;
  };
  fixedDofs_ = dofsOf(fixedNodes);
  *dirichlet_ = DirichletRows(system_, fixedDofs_);
  kinematicNodes_.clear();
  if (!multigrid_) return;
  // Rediscretized levels: a coarse node is held still where most of the
  // weight it spreads to the finer level lands on fixed nodes there (e.g.
  // the coarse nodes of a clamped base); a free coarse operator next to a
  // clamped fine one would send near-rigid corrections the fine grid cannot
  // take. Galerkin operators inherit the constraint through P instead.
  std::vector<std::vector<char>> perLevel{fixedNodes};
  for (std::size_t l = 0; l < coarse_.size(); ++l) {
    const SparseMatrix& P = prolongations_[l];  // finer x coarse
    Eigen::VectorXd fixedWeight = Eigen::VectorXd::Zero(P.cols()), weight = fixedWeight;
    for (int row = 0; row < P.outerSize(); ++row)
      for (SparseMatrix::InnerIterator it(P, row); it; ++it) {
        weight[it.col()] += std::abs(it.value());
        if (perLevel[l][static_cast<std::size_t>(row)])
          fixedWeight[it.col()] += std::abs(it.value());
      }
    std::vector<char> coarseFixed(static_cast<std::size_t>(P.cols()), 0);
    for (Index c = 0; c < P.cols(); ++c)
      coarseFixed[static_cast<std::size_t>(c)] = weight[c] > 0 && fixedWeight[c] >= 0.5 * weight[c];
    coarse_[l].dirichlet = DirichletRows(coarseSystems_[l], dofsOf(coarseFixed));
    perLevel.push_back(std::move(coarseFixed));
  }
  // (The multigrid takes new coarse operators at its next setup: the
  // coarse systems' Dirichlet rows changed.)
  multigrid_->setFixedNodesPerLevel(perLevel);
}

void Simulation::setKinematicTargets(const std::vector<int>& nodes, const Points3& targets) {
  if (static_cast<Index>(nodes.size()) != targets.rows())
    throw Error("one target per kinematic node");
  std::vector<int> internal;
  for (int v : nodes) {
    if (v < 0 || v >= rest_.nodeCount() ||
        !fixedDofs_[3 * static_cast<std::size_t>(rank_[static_cast<std::size_t>(v)])])
      throw Error("kinematic node " + std::to_string(v) + " must be a fixed node");
    internal.push_back(rank_[static_cast<std::size_t>(v)]);
  }
  kinematicNodes_ = std::move(internal);
  kinematicTargets_ = targets;
}

void Simulation::setExternalForces(const Points3& forces) {
  requireRows("external forces", forces.rows(), rest_.nodeCount(), "nodes");
  std::lock_guard lock(mutex_);
  external_ = toInternal(forces);
}

Points3 Simulation::externalForces() const {
  std::lock_guard lock(mutex_);
  return toOutside(external_);
}

void Simulation::setPositions(const Points3& positions) {
  requireRows("positions", positions.rows(), rest_.nodeCount(), "nodes");
  std::lock_guard lock(mutex_);
  x_ = toInternal(positions);
  acceleration_.setZero();  // (a new start, not the outcome of a step)
}

void Simulation::setVelocities(const Points3& velocities) {
  requireRows("velocities", velocities.rows(), rest_.nodeCount(), "nodes");
  std::lock_guard lock(mutex_);
  v_ = toInternal(velocities);
  acceleration_.setZero();
}

void Simulation::buildSystem(double h, StepStats& stats) {
  const ElasticMaterial& m = options_.material;
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  {
    std::lock_guard lock(mutex_);
    stepExternal_ = external_;
  }
  // Floor contact: a penalty spring on every node below the plane, its
  // stiffness on the system's diagonal like the mass.
  stats.contacts = 0;
  const Eigen::VectorXd* diagonal = &dampedMass_;
  if (options_.floorHeight) {
    contactDiagonal_.setZero(fem_.dofCount());
    contactForce_.setZero(fem_.dofCount());
    for (Index v = 0; v < rest_.nodeCount(); ++v) {
      const Index dof = 3 * v + axisIndex(options_.up);
      const double depth = *options_.floorHeight - x_[dof];
      if (depth < 0) continue;  // touching counts: the penalty keeps it from sinking
      ++stats.contacts;
      contactDiagonal_[dof] = h * h * floorStiffness_;
      contactForce_[dof] = floorStiffness_ * depth - h * floorStiffness_ * v_[dof];
    }
    systemDiagonal_ = dampedMass_ + contactDiagonal_;
    diagonal = &systemDiagonal_;
  }
  // A = (1 + h alpha) M + (h beta + h^2) K + h^2 K_rot (+ contact) and
  // f_el - (beta + h) K v - h K_rot v, in one element pass (K_rot only with
  // the full tangent, its compressive modes dropped from the matrix only:
  // CorotatedFem::SystemTerms; damping stays beta K, which leaves a stressed
  // body's rigid rotation undamped); then b = h (f_el - (beta + h) K v - h K_rot v
  // + M g + f_ext - alpha M v + f_contact).
  auto start = std::chrono::steady_clock::now();
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = h * m.stiffnessDamping + h * h;
  terms.diagonal = diagonal;
  terms.velocity = &v_;
  terms.velocityWeight = m.stiffnessDamping + h;
  if (options_.tangent == Tangent::Full) {
    terms.rotationScale = h * h;
    terms.rotationVelocityWeight = h;
  }
  fem_.update(x_, force_, system_, terms);
  stats.assemblySeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rhs_.resize(force_.size());
  for (Index v = 0; v < rest_.nodeCount(); ++v)
    rhs_.segment<3>(3 * v) = h * (force_.segment<3>(3 * v) + stepExternal_.segment<3>(3 * v) +
                                  mass.segment<3>(3 * v).cwiseProduct(
                                      options_.gravity - m.massDamping * v_.segment<3>(3 * v)));
  if (options_.floorHeight) rhs_ += h * contactForce_;

  // Dirichlet: prescribed dv for fixed dofs (to reach kinematic targets, or
  // to stop), moved to the right-hand side, then identity rows and columns.
  prescribedDv_.setZero();
  for (std::size_t d = 0; d < fixedDofs_.size(); ++d)
    if (fixedDofs_[d]) prescribedDv_[static_cast<Index>(d)] = -v_[static_cast<Index>(d)];
  for (std::size_t i = 0; i < kinematicNodes_.size(); ++i) {
    const Index v = kinematicNodes_[i];
    const Eigen::Vector3d target = kinematicTargets_.row(static_cast<Index>(i)).transpose();
    prescribedDv_.segment<3>(3 * v) = (target - x_.segment<3>(3 * v)) / h - v_.segment<3>(3 * v);
  }
  dirichlet_->apply(system_, &rhs_, &prescribedDv_);
}

void Simulation::buildCoarseSystems(double h) {
  const ElasticMaterial& m = options_.material;
  CorotatedFem::SystemTerms terms;
  terms.stiffnessScale = h * m.stiffnessDamping + h * h;
  if (options_.tangent == Tangent::Full) terms.rotationScale = h * h;
  const Eigen::VectorXd* finer = &x_;
  const Eigen::VectorXd* finerContact = options_.floorHeight ? &contactDiagonal_ : nullptr;
  for (std::size_t l = 0; l < coarse_.size(); ++l) {
    CoarseLevel& level = coarse_[l];
    multiplyNodal(level.positionsFromFiner, *finer, level.x);
    terms.diagonal = &level.dampedMass;
    if (finerContact) {
      // The floor's penalty springs, lumped onto the coarse nodes (P^T D 1).
      multiplyNodal(level.restrictionToCoarse, *finerContact, level.contactDiagonal);
      level.diagonal = level.dampedMass + level.contactDiagonal;
      terms.diagonal = &level.diagonal;
      finerContact = &level.contactDiagonal;
    }
    level.fem.update(level.x, level.force, coarseSystems_[l], terms);
    level.dirichlet.apply(coarseSystems_[l]);
    finer = &level.x;
  }
}

StepStats Simulation::step() {
  StepStats stats;
  const double h = options_.timeStep;
  buildSystem(h, stats);
  stats.solver = choice_ ? choice_->next() : options_.solver;
  const bool multigrid = stats.solver == SolverKind::Multigrid;
  auto start = std::chrono::steady_clock::now();
  if (!multigrid) {
    blockJacobi_->setup(system_);
  } else {
    // Coarse operators left from before a spell of CG steps are stale:
    // rebuild them.
    if (choice_ && steps_ - lastMultigridStep_ > options_.coarseReuse) multigrid_->renewCoarse();
    lastMultigridStep_ = steps_;
    if (coarse_.empty()) {
      multigrid_->setup(system_);
    } else {
      // Rediscretized multigrid: new coarse systems when the multigrid takes
      // them (every coarseReuse steps).
      if (multigrid_->coarseDue()) buildCoarseSystems(h);
      multigrid_->setup(system_, coarseSystems_);
    }
  }
  blockSystem_.assign(system_);
  stats.setupSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  guess_.guess(blockSystem_, rhs_, dv_);  // (dv_ holds the last solution: the plain warm start)
  const Preconditioner& preconditioner =
      multigrid ? static_cast<const Preconditioner&>(*multigrid_) : *blockJacobi_;
  const SolveStats solve = conjugateGradient(blockSystem_, rhs_, dv_, preconditioner,
                                             options_.tolerance, options_.maxIterations);
  stats.solveSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (choice_)
    choice_->record(stats.setupSeconds + stats.solveSeconds,
                    solve.relativeResidual <= options_.tolerance);
  stats.iterations = solve.iterations;
  stats.residual = solve.relativeResidual;
  Eigen::VectorXd v = v_ + dv_;
  Eigen::VectorXd x = x_ + h * v;
  for (std::size_t i = 0; i < kinematicNodes_.size(); ++i)  // exact, free of round-off
    x.segment<3>(3 * kinematicNodes_[i]) = kinematicTargets_.row(static_cast<Index>(i)).transpose();
  if (options_.floorHeight) {
    const int up = axisIndex(options_.up);
    for (Index node = 0; node < rest_.nodeCount(); ++node) {
      if (x[3 * node + up] >= *options_.floorHeight) continue;
      x[3 * node + up] = *options_.floorHeight;
      v[3 * node + up] = std::max(v[3 * node + up], 0.0);
      v[3 * node + (up + 1) % 3] *= 1 - options_.friction;
      v[3 * node + (up + 2) % 3] *= 1 - options_.friction;
    }
  }
  // The state stays the last one that was fine. (A solve that overflowed
  // spreads NaN over every node through CG's dot products: no node to name.)
  const std::string problem = dv_.allFinite()
                                  ? firstBlownUpNode(x, v, order_)
                                  : std::string("the solver's velocity update is not finite");
  if (!problem.empty())
    throw Error("the simulation diverged in step " + std::to_string(steps_ + 1) +
                " (t = " + formatNumber(time_ + h) + " s): " + problem +
                "; smaller loads or time steps, or a stiffer material, may keep it stable");
  guess_.remember(dv_);
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
  return {toOutside(x_), toOutside(v_), toOutside(appliedExternal_), toOutside(acceleration_),
          time_,         steps_};
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
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  e.kinetic = 0.5 * v.dot(mass.cwiseProduct(v));
  e.elastic = fem_.elasticEnergy(x);
  for (Index node = 0; node < internal_.nodeCount(); ++node)
    e.gravitational -= mass[3 * node] * options_.gravity.dot(x.segment<3>(3 * node) -
                                                             internal_.nodes.row(node).transpose());
  return e;
}

Points3 Simulation::reactionForces(const SimulationState& state) const {
  Points3 reactions = Points3::Zero(rest_.nodeCount(), 3);
  if (fixedNodes_.empty()) return reactions;
  const ElasticMaterial& m = options_.material;
  const Eigen::VectorXd internalForce = fem_.dampedElasticForce(
      toInternal(state.positions), toInternal(state.velocities), m.stiffnessDamping);
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  for (int node : fixedNodes_) {
    const Index i = 3 * rank_[static_cast<std::size_t>(node)];
    const Eigen::Vector3d inertia = mass.segment<3>(i).cwiseProduct(
        state.accelerations.row(node).transpose() +
        m.massDamping * state.velocities.row(node).transpose() - options_.gravity);
    reactions.row(node) = inertia.transpose() - internalForce.segment<3>(i).transpose() -
                          state.externalForces.row(node);
  }
  return reactions;
}

Eigen::Vector3d Simulation::supportReaction(const SimulationState& state) const {
  return reactionForces(state).colwise().sum().transpose();
}

FrameFields Simulation::frameFields(const SimulationState& state) const {
  return {state.positions, state.velocities, state.externalForces, reactionForces(state),
          fem_.vonMisesStress(toInternal(state.positions))};
}

}  // namespace tetskin
