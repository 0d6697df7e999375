// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The linear solve of each step, A dv = b: CG preconditioned by block
// Jacobi, CG with a multigrid V-cycle over the solver's own grid levels
// (GridHierarchy.h; Galerkin coarse operators) or over the dataset's coarser
// levels (their operators Galerkin products or their own FEM,
// rediscretized), or
// whichever of the two is faster on the running simulation (SolverChoice.h);
// every solve starts from the projected guess of the last solutions
// (ProjectedInitialGuess.h). Another solver is added here (and to
// SolverKind): the stepper hands over the system and takes dv back.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ForceModel.h"
#include "tetskin/simulation/LinearSolvers.h"
#include "tetskin/simulation/ProjectedInitialGuess.h"

namespace tetskin {

class SolverStack {
 public:
  // For the system of `level` of `dataset`, `mesh` being that level in the
  // stepper's internal numbering; the coarser levels (multigrid) are read
  // and checked here, named after `datasetName` in errors. `coarse` says
  // how a coarse level's own FEM becomes a coarse operator (rediscretized).
  // The dataset's levels are read only where the options ask for them.
  SolverStack(const MultiLevelTetMesh& dataset, int level, const TetMesh& mesh,
              const SimulationOptions& options, const CoarseDiscretization& coarse,
              const std::string& datasetName);
  ~SolverStack();

  // SolverKind::Automatic: its trials and choice (null otherwise).
  const SolverChoice* choice() const { return choice_ ? &*choice_ : nullptr; }

  // One flag per node of the level (internal numbering), 1 = fixed.
  void setFixedNodes(const std::vector<char>& fixedNodes);

  // What a rediscretized coarse operator is built at: the step's positions
  // and the springs' share of its diagonal (null: no spring acted).
  // And the system's springs outside A's pattern (null: none; a part of
  // the system, which every solver's products include).
  struct StepPoint {
    const Eigen::VectorXd* positions = nullptr;
    const Eigen::VectorXd* springs = nullptr;
    const CouplingSprings* coupling = nullptr;
  };
  // Solves A dv = b (dv: the last solution on entry, the new one on
  // return) for the step numbered `step` from 0; fills the stats' solver
  // and its setup and solve seconds.
  SolveStats solve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& dv, Index step,
                   const StepPoint& at, StepStats& stats);
  // The same step's system again, a little changed (contacts let go): by
  // `solver` from dv as it is (the first solve's answer, near the new
  // one), outside the solver choice's trials; its statistics added to
  // `stats`.
  SolveStats resolve(SolverKind solver, const SparseMatrix& A, const Eigen::VectorXd& b,
                     Eigen::VectorXd& dv, Index step, const StepPoint& at, StepStats& stats);
  // A solution the stepper kept (its step did not blow up): the next
  // guesses build on it.
  void remember(const Eigen::VectorXd& dv) { guess_.remember(dv); }

 private:
  // The multigrid's coarse levels from the dataset's coarser levels (and
  // their own FEM where the coarse operators are rediscretized).
  void datasetLevels(const MultiLevelTetMesh& dataset, int level, const TetMesh& mesh,
                     const SimulationOptions& options, const CoarseDiscretization& coarse,
                     const std::string& datasetName);
  // One solve of the step by `solver` (setup included; with `guess`, from
  // the projected guess and after copying A, else from dv as it is),
  // stopped once it has taken `budgetSeconds` (amortized as below).
  struct Outcome {
    SolveStats solve;
    double setupSeconds = 0, solveSeconds = 0;
    double amortizedSeconds = 0;  // with a coarse rebuild's share, as a run pays it
  };
  Outcome solveWith(SolverKind solver, const SparseMatrix& A, const Eigen::VectorXd& b,
                    Eigen::VectorXd& dv, Index step, const StepPoint& at, bool guess,
                    double budgetSeconds);
  // Rediscretized multigrid: the coarse systems at the step's point.
  void buildCoarseSystems(const StepPoint& at);

  SimulationOptions options_;
  CoarseDiscretization discretization_;
  std::unique_ptr<Preconditioner> cgPreconditioner_;    // cg (or the caller's), auto
  std::unique_ptr<MultigridPreconditioner> multigrid_;  // multigrid, auto
  std::optional<SolverChoice> choice_;                  // auto
  Index lastMultigridStep_ = -1;                        // the last step multigrid solved
  double lastFinestSetupSeconds_ = 0;  // the last multigrid setup without a coarse rebuild
  struct CoarseLevel;                  // rediscretized: one per coarser level
  std::vector<CoarseLevel> coarse_;    // the next coarser first
  std::vector<SparseMatrix> coarseSystems_;
  std::vector<SparseMatrix> prolongations_;  // nodal, level l+1 to level l (l = 0: this one)
  NodeBlockMatrix blockSystem_;              // A's copy for CG's products
  ProjectedInitialGuess guess_;
};

}  // namespace tetskin
