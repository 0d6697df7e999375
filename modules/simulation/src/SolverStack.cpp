// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SolverStack.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "NodeConstraints.h"
#include "NodeNumbering.h"
#include "tetskin/simulation/GridHierarchy.h"
#include "tetskin/simulation/Prolongation.h"

namespace tetskin {

// A coarser level of the rediscretized multigrid: its own corotated FEM at
// positions interpolated from the next finer level's.
struct SolverStack::CoarseLevel {
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

static_assert(simulation_option::kGuessSolutions.range.max == kMaxProductColumns,
              "the guess's solutions are those one pass over A multiplies");

namespace {

// The automatic solver's samples of the other solver, after the first
// ones: one in this many steps (two thirds of a second at 60 steps/s; a
// losing sample costs about one step more, so 3 in 120 steps).
constexpr int kSamplePeriod = 40;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SolverStack::SolverStack(const MultiLevelTetMesh& dataset, int level, const TetMesh& mesh,
                         const SimulationOptions& options, const CoarseDiscretization& coarse,
                         const std::string& datasetName)
    : options_(options), discretization_(coarse), guess_(options.guessSolutions) {
  if (options.solver != SolverKind::Multigrid)
    cgPreconditioner_ = options.preconditioner && options.solver == SolverKind::ConjugateGradient
                            ? options.preconditioner()
                            : std::make_unique<SpringGaussSeidel>();
  if (options.solver == SolverKind::Automatic) choice_.emplace(kSamplePeriod);
  if (options.solver == SolverKind::ConjugateGradient) return;
  if (options.coarseLevels == CoarseLevels::Grid) {
    prolongations_ = enclosingGrids(mesh).prolongations();
  } else {
    datasetLevels(dataset, level, mesh, options, coarse, datasetName);
  }
  multigrid_ = std::make_unique<MultigridPreconditioner>(prolongations_);
  multigrid_->setCoarseReuse(options.coarseReuse);
  multigrid_->setSinglePrecision(options.singlePrecisionCycle);
  multigrid_->setSmoother(options.smoother);
}

void SolverStack::datasetLevels(const MultiLevelTetMesh& dataset, int level, const TetMesh& mesh,
                                const SimulationOptions& options,
                                const CoarseDiscretization& coarse,
                                const std::string& datasetName) {
  // This level, then the coarser ones, each renumbered breadth first.
  std::vector<TetMesh> meshes{mesh};
  for (int coarser = level - 1; coarser >= 0; --coarser) {
    // (Named as such: a broken coarse level stops the multigrid only.)
    meshes.push_back(renumberedBreadthFirst(
        extractLevel(dataset, coarser),
        levelName(datasetName, coarser) + " (a coarser level, used by the multigrid solver)"));
    prolongations_.push_back(nodalProlongation(meshes.back(), meshes[meshes.size() - 2].nodes));
  }
  if (options.coarseOperators == CoarseOperators::Rediscretized) {
    coarse_.reserve(meshes.size() - 1);
    for (std::size_t l = 1; l < meshes.size(); ++l) {
      CoarseLevel& coarseLevel = coarse_.emplace_back(meshes[l], options.material, meshes[l - 1]);
      coarseLevel.dampedMass = coarse.massScale * coarseLevel.fem.lumpedMass();
      coarseLevel.restrictionToCoarse = prolongations_[l - 1].transpose();
      coarseSystems_.push_back(coarseLevel.fem.pattern());
    }
  }
}

SolverStack::~SolverStack() = default;

void SolverStack::setFixedNodes(const std::vector<char>& fixedNodes) {
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

void SolverStack::buildCoarseSystems(const StepPoint& at) {
  CorotatedFem::SystemTerms terms = discretization_.terms;
  const Eigen::VectorXd* finer = at.positions;
  const Eigen::VectorXd* finerContact = at.springs;
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

SolverStack::Outcome SolverStack::solveWith(SolverKind solver, const SparseMatrix& A,
                                            const Eigen::VectorXd& b, Eigen::VectorXd& dv,
                                            Index step, const StepPoint& at, bool guess,
                                            double budgetSeconds) {
  const bool multigrid = solver == SolverKind::Multigrid;
  Outcome outcome;
  auto start = std::chrono::steady_clock::now();
  bool coarseBuilt = false;
  if (!multigrid) {
    cgPreconditioner_->setCoupling(at.coupling);
    cgPreconditioner_->setup(A);
  } else {
    // Coarse operators left from before a spell of CG steps are stale:
    // rebuild them.
    if (choice_ && step - lastMultigridStep_ > options_.coarseReuse) multigrid_->renewCoarse();
    lastMultigridStep_ = step;
    coarseBuilt = multigrid_->coarseDue();
    if (coarse_.empty()) {
      multigrid_->setup(A);
    } else {
      // Rediscretized multigrid: new coarse systems when the multigrid takes
      // them (every coarseReuse steps).
      if (coarseBuilt) buildCoarseSystems(at);
      multigrid_->setup(A, coarseSystems_);
    }
  }
  if (guess) blockSystem_.assign(A);
  outcome.setupSeconds = secondsSince(start);
  // The setup as a run of this solver pays it: a coarse rebuild spread over
  // the steps that reuse it (the rest, the finest level's, every step).
  double amortizedSetup = outcome.setupSeconds;
  if (multigrid && coarseBuilt && options_.coarseReuse > 1) {
    const double finest = std::min(lastFinestSetupSeconds_, outcome.setupSeconds);
    amortizedSetup = finest + (outcome.setupSeconds - finest) / options_.coarseReuse;
  } else if (multigrid) {
    lastFinestSetupSeconds_ = outcome.setupSeconds;
  }
  start = std::chrono::steady_clock::now();
  if (guess)
    guess_.guess(blockSystem_, b, dv);  // (dv holds the last solution: the plain warm start)
  const Preconditioner& preconditioner =
      multigrid ? static_cast<const Preconditioner&>(*multigrid_) : *cgPreconditioner_;
  const auto deadline =
      std::isfinite(budgetSeconds)
          ? start +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(std::max(0.0, budgetSeconds - amortizedSetup)))
          : std::chrono::steady_clock::time_point::max();
  outcome.solve = conjugateGradient(blockSystem_, b, dv, preconditioner, options_.tolerance,
                                    options_.maxIterations, deadline, at.coupling);
  outcome.solveSeconds = secondsSince(start);
  outcome.amortizedSeconds = amortizedSetup + outcome.solveSeconds;
  return outcome;
}

SolveStats SolverStack::solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& dv,
                              Index step, const StepPoint& at, StepStats& stats) {
  const SolverChoice::Turn turn =
      choice_ ? choice_->next()
              : SolverChoice::Turn{options_.solver, false, std::numeric_limits<double>::infinity()};
  Outcome outcome = solveWith(turn.solver, A, b, dv, step, at, true, turn.budgetSeconds);
  stats.solver = turn.solver;
  stats.setupSeconds = outcome.setupSeconds;
  stats.solveSeconds = outcome.solveSeconds;
  stats.iterations = outcome.solve.iterations;
  const bool cutOff = outcome.solve.stoppedAtDeadline;
  if (choice_)
    choice_->record(outcome.amortizedSeconds, outcome.solve.relativeResidual <= options_.tolerance,
                    cutOff);
  if (cutOff) {
    // A sample out of its budget: the preferred solver finishes the step
    // from the sample's last iterate.
    const Outcome finish = solveWith(choice_->preferred(), A, b, dv, step, at, false,
                                     std::numeric_limits<double>::infinity());
    stats.solver = choice_->preferred();
    stats.setupSeconds += finish.setupSeconds;
    stats.solveSeconds += finish.solveSeconds;
    stats.iterations += finish.solve.iterations;
    outcome.solve = finish.solve;
  }
  stats.residual = outcome.solve.relativeResidual;
  return outcome.solve;
}

SolveStats SolverStack::resolve(SolverKind solver, const SparseMatrix& A, const Eigen::VectorXd& b,
                                Eigen::VectorXd& dv, Index step, const StepPoint& at,
                                StepStats& stats) {
  blockSystem_.assign(A);  // (solveWith assigns it only where it guesses)
  const Outcome outcome = solveWith(solver, A, b, dv, step, at, /*guess=*/false,
                                    std::numeric_limits<double>::infinity());
  stats.setupSeconds += outcome.setupSeconds;
  stats.solveSeconds += outcome.solveSeconds;
  stats.iterations += outcome.solve.iterations;
  stats.residual = outcome.solve.relativeResidual;
  return outcome.solve;
}

}  // namespace tetskin
