// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What a solver researcher would use instead of TetSkin's solvers, as
// preconditioners of the stepper's CG (SimulationOptions::preconditioner),
// so that they solve the stepper's own systems to the same tolerance:
// - CHOLMOD's supernodal Cholesky factor of the system (SuiteSparse),
//   refactorized every `refactorEvery` steps: every step, a sparse direct
//   solve (CG then stops after one iteration); every k steps, the factor
//   of an earlier system preconditions CG (Hecht et al. 2012), its
//   factorization's time falling on the steps that make it.
// - hypre's BoomerAMG (one V-cycle per CG iteration), nodal for 3 unknowns
//   per node, its hierarchy set up every `setupEvery` steps (as TetSkin's
//   multigrid reuses its coarse operators) and the fine level's values
//   updated on every step.
// Benchmark dependencies only (tests/bench/CMakeLists.txt).

#include <memory>

#include "tetskin/simulation/LinearSolvers.h"

namespace tetskin::bench {

std::unique_ptr<Preconditioner> cholmodFactor(int refactorEvery);
std::unique_ptr<Preconditioner> boomerAmg(int setupEvery);

// hypre needs MPI: call once before boomerAmg's first setup, and
// finalize at the end of main.
void startMpi(int& argc, char**& argv);
void finishMpi();

}  // namespace tetskin::bench
