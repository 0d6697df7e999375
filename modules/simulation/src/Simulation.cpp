// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Simulation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

#include "tetskin/core/Error.h"
#include "tetskin/simulation/Prolongation.h"

namespace tetskin {

const char* toString(SolverKind kind) {
  return kind == SolverKind::ConjugateGradient ? "cg" : "multigrid";
}

namespace {

Eigen::VectorXd flatten(const Points3& p) {
  return Eigen::Map<const Eigen::VectorXd>(p.data(), p.size());
}

Points3 unflatten(const Eigen::VectorXd& x) {
  return Eigen::Map<const Points3>(x.data(), x.size() / 3, 3);
}

}  // namespace

Simulation::Simulation(const MultiLevelTetMesh& dataset, int level,
                       const SimulationOptions& options)
    : level_(level < 0 ? dataset.finestLevel() : level),
      rest_(extractLevel(dataset, level_)),
      options_(options),
      fem_(rest_, options.material) {
  if (!(options.timeStep > 0)) throw Error("the time step must be positive");
  if (options.coarseReuse < 1) throw Error("the coarse-operator reuse must be at least 1 step");
  x_ = fem_.restPositions();
  v_.setZero(fem_.dofCount());
  external_.setZero(fem_.dofCount());
  dv_.setZero(fem_.dofCount());
  prescribedDv_.setZero(fem_.dofCount());
  fixedDofs_.assign(static_cast<std::size_t>(fem_.dofCount()), 0);
  stiffness_ = fem_.pattern();
  system_ = fem_.pattern();
  diagonalSlot_.resize(static_cast<std::size_t>(fem_.dofCount()));
  for (int row = 0; row < system_.rows(); ++row) {
    const int* begin = system_.innerIndexPtr() + system_.outerIndexPtr()[row];
    const int* end = system_.innerIndexPtr() + system_.outerIndexPtr()[row + 1];
    diagonalSlot_[static_cast<std::size_t>(row)] =
        static_cast<int>(std::lower_bound(begin, end, row) - system_.innerIndexPtr());
  }
  if (options.solver == SolverKind::Multigrid) {
    std::vector<SparseMatrix> prolongations;
    Points3 fine = rest_.nodes;
    for (int coarse = level_ - 1; coarse >= 0; --coarse) {
      const TetMesh coarseMesh = extractLevel(dataset, coarse);
      prolongations.push_back(nodalProlongation(coarseMesh, fine));
      fine = coarseMesh.nodes;
    }
    auto mg = std::make_unique<MultigridPreconditioner>(std::move(prolongations));
    mg->setCoarseReuse(options.coarseReuse);
    multigrid_ = mg.get();
    preconditioner_ = std::move(mg);
  } else {
    preconditioner_ = std::make_unique<BlockJacobi>();
  }
  // Automatic floor stiffness: about a hundred times the stiffest element
  // diagonal, so penetration stays small without ruining the conditioning.
  floorStiffness_ = options.floorStiffness;
  if (options.floorHeight && !(floorStiffness_ > 0)) {
    Eigen::VectorXd force;
    fem_.update(x_, force, stiffness_);
    floorStiffness_ = 100.0 * stiffness_.diagonal().maxCoeff();
  }
}

Simulation::~Simulation() = default;

void Simulation::setFixedNodes(const std::vector<int>& nodes) {
  fixedNodes_ = nodes;
  std::fill(fixedDofs_.begin(), fixedDofs_.end(), 0);
  for (int v : nodes) {
    if (v < 0 || v >= rest_.nodeCount())
      throw Error("fixed node " + std::to_string(v) + " does not exist");
    for (int a = 0; a < 3; ++a) fixedDofs_[static_cast<std::size_t>(3 * v + a)] = 1;
  }
  if (multigrid_) {
    std::vector<char> fixedNodes(static_cast<std::size_t>(rest_.nodeCount()), 0);
    for (int v : nodes) fixedNodes[static_cast<std::size_t>(v)] = 1;
    multigrid_->setFixedNodes(fixedNodes);
  }
  kinematicNodes_.clear();
}

void Simulation::setKinematicTargets(const std::vector<int>& nodes, const Points3& targets) {
  if (static_cast<Index>(nodes.size()) != targets.rows())
    throw Error("one target per kinematic node");
  for (int v : nodes)
    if (!fixedDofs_[static_cast<std::size_t>(3 * v)])
      throw Error("kinematic node " + std::to_string(v) + " must be a fixed node");
  kinematicNodes_ = nodes;
  kinematicTargets_ = targets;
}

void Simulation::setExternalForces(const Points3& forces) {
  if (forces.rows() != rest_.nodeCount()) throw Error("one external force per node");
  std::lock_guard lock(mutex_);
  external_ = flatten(forces);
}

Points3 Simulation::externalForces() const {
  std::lock_guard lock(mutex_);
  return unflatten(external_);
}

void Simulation::setPositions(const Points3& positions) {
  if (positions.rows() != rest_.nodeCount()) throw Error("one position per node");
  std::lock_guard lock(mutex_);
  x_ = flatten(positions);
}

void Simulation::setVelocities(const Points3& velocities) {
  if (velocities.rows() != rest_.nodeCount()) throw Error("one velocity per node");
  std::lock_guard lock(mutex_);
  v_ = flatten(velocities);
}

void Simulation::buildSystem(double h, StepStats& stats) {
  const ElasticMaterial& m = options_.material;
  const Eigen::VectorXd& mass = fem_.lumpedMass();
  Eigen::VectorXd external;
  {
    std::lock_guard lock(mutex_);
    external = external_;
  }
  auto start = std::chrono::steady_clock::now();
  fem_.update(x_, force_, stiffness_);
  stats.assemblySeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // f = f_el + M g + f_ext
  for (Index v = 0; v < rest_.nodeCount(); ++v)
    force_.segment<3>(3 * v) +=
        mass.segment<3>(3 * v).cwiseProduct(options_.gravity) + external.segment<3>(3 * v);
  // A = (1 + h alpha) M + (h beta + h^2) K;  b = h (f - alpha M v - (beta + h) K v)
  multiply(stiffness_, v_, scratch_);
  rhs_ = h * (force_ - m.massDamping * mass.cwiseProduct(v_) - (m.stiffnessDamping + h) * scratch_);
  const double kScale = h * m.stiffnessDamping + h * h;
  const double* k = stiffness_.valuePtr();
  double* a = system_.valuePtr();
  for (Index i = 0; i < system_.nonZeros(); ++i) a[i] = kScale * k[i];
  for (Index r = 0; r < system_.rows(); ++r)
    a[diagonalSlot_[static_cast<std::size_t>(r)]] += (1 + h * m.massDamping) * mass[r];

  // Floor contact: a penalty spring on every node below the plane.
  stats.contacts = 0;
  if (options_.floorHeight) {
    for (Index v = 0; v < rest_.nodeCount(); ++v) {
      const Index dof = 3 * v + 1;
      const double depth = *options_.floorHeight - x_[dof];
      if (depth < 0) continue;  // touching counts: the penalty keeps it from sinking
      ++stats.contacts;
      a[diagonalSlot_[static_cast<std::size_t>(dof)]] += h * h * floorStiffness_;
      rhs_[dof] += h * (floorStiffness_ * depth - h * floorStiffness_ * v_[dof]);
    }
  }

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
  const int* outer = system_.outerIndexPtr();
  const int* inner = system_.innerIndexPtr();
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(system_.rows()), 1024),
                    [&](const auto& range) {
                      for (int row = range.begin(); row != range.end(); ++row) {
                        if (fixedDofs_[static_cast<std::size_t>(row)]) {
                          for (int s = outer[row]; s < outer[row + 1]; ++s)
                            a[s] = inner[s] == row ? 1.0 : 0.0;
                          rhs_[row] = prescribedDv_[row];
                          continue;
                        }
                        for (int s = outer[row]; s < outer[row + 1]; ++s)
                          if (fixedDofs_[static_cast<std::size_t>(inner[s])]) {
                            rhs_[row] -= a[s] * prescribedDv_[inner[s]];
                            a[s] = 0.0;
                          }
                      }
                    });
}

StepStats Simulation::step() {
  StepStats stats;
  const double h = options_.timeStep;
  buildSystem(h, stats);
  auto start = std::chrono::steady_clock::now();
  preconditioner_->setup(system_);
  stats.setupSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  const SolveStats solve = conjugateGradient(system_, rhs_, dv_, *preconditioner_,
                                             options_.tolerance, options_.maxIterations);
  stats.solveSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.iterations = solve.iterations;
  stats.residual = solve.relativeResidual;
  if (!dv_.allFinite()) throw Error("the simulation diverged (non-finite velocity update)");
  Eigen::VectorXd v = v_ + dv_;
  Eigen::VectorXd x = x_ + h * v;
  for (std::size_t i = 0; i < kinematicNodes_.size(); ++i)  // exact, free of round-off
    x.segment<3>(3 * kinematicNodes_[i]) = kinematicTargets_.row(static_cast<Index>(i)).transpose();
  if (options_.floorHeight) {
    for (Index node = 0; node < rest_.nodeCount(); ++node) {
      if (x[3 * node + 1] >= *options_.floorHeight) continue;
      x[3 * node + 1] = *options_.floorHeight;
      v[3 * node + 1] = std::max(v[3 * node + 1], 0.0);
      v[3 * node] *= 1 - options_.friction;
      v[3 * node + 2] *= 1 - options_.friction;
    }
  }
  std::lock_guard lock(mutex_);
  x_ = std::move(x);
  v_ = std::move(v);
  time_ += h;
  ++steps_;
  return stats;
}

SimulationState Simulation::state() const {
  std::lock_guard lock(mutex_);
  return {unflatten(x_), unflatten(v_), time_, steps_};
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
  for (Index node = 0; node < rest_.nodeCount(); ++node)
    e.gravitational -= mass[3 * node] * options_.gravity.dot(x.segment<3>(3 * node));
  return e;
}

Eigen::VectorXd Simulation::vonMisesStress() const {
  Eigen::VectorXd x;
  {
    std::lock_guard lock(mutex_);
    x = x_;
  }
  return fem_.vonMisesStress(x);
}

}  // namespace tetskin
