// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The automatic solver: which of block-Jacobi CG and multigrid CG solves a
// simulation's steps faster, found by timing both on the running simulation.
//
// Neither wins everywhere: a multigrid iteration costs several CG iterations
// and its coarse operators cost a setup, so CG is faster on small or soft
// bodies (fewer CG iterations) and multigrid on large or stiff ones; where
// the two cross depends on the mesh, the material, the motion and the
// machine (at the default material on our 2-core machine, CG was about twice
// as fast at 12.7k elements; at 109k multigrid was 1.3-1.6x as fast over the
// benchmark's steps and CG slightly faster over the first 60-180). So the
// two are compared where it matters: a round of `trialSteps` steps of each,
// alternated (the state drifts alike for both), then `period` steps with the
// one whose trial steps took less time in all, then the next round, so a
// change of regime (a body coming to rest, a stiffer contact) is followed.
// The very first two steps (CG, then multigrid) are not timed: they carry
// one-time costs (the multigrid's Galerkin streams, the first allocations)
// that would count against a solver for good.
// Both solve every step to the same tolerance, so the choice moves the
// trajectory by no more than the solves' tolerance does, except where a
// solve stops at the iteration limit short of it (CG on a nearly
// incompressible body, nu = 0.4999): its step is then inexact, and its time
// says nothing about the time to reach the tolerance. So the solver with
// fewer such steps in a round's trials is preferred whatever the times; the
// times decide between equals.

#include <string>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

enum class SolverKind { ConjugateGradient, Multigrid, Automatic };
template <>
struct EnumSchema<SolverKind> {
  static constexpr const char* what = "solver";
  static constexpr EnumValue<SolverKind> values[] = {
      {SolverKind::Automatic, "auto", "whichever of the two is faster here, timed every 120 steps"},
      {SolverKind::ConjugateGradient, "cg", "block-Jacobi CG"},
      {SolverKind::Multigrid, "multigrid", "CG with a V-cycle"}};
};

class SolverChoice {
 public:
  SolverChoice(int trialSteps, int period);
  // The solver of the coming step: ConjugateGradient or Multigrid.
  SolverKind next() const;
  // The time the step of next() took (its preconditioner's setup and
  // solve), and whether its solve reached the tolerance.
  void record(double seconds, bool reachedTolerance);
  // The one chosen in the last round (ConjugateGradient before the first).
  SolverKind preferred() const { return preferred_; }
  // Whether that round was decided by solves stopped short of the
  // tolerance rather than by the times.
  bool decidedByShortfalls() const { return decidedByShortfalls_; }
  // Rounds of trials completed.
  int rounds() const { return rounds_; }

 private:
  int trialSteps_, period_;
  // Step within the round: trials first, then the period; -2 and -1 are the
  // untimed first steps.
  int position_ = -2;
  double trialSeconds_[2] = {0, 0};  // CG, multigrid
  int trialShortfalls_[2] = {0, 0};  // trial steps stopped short of the tolerance
  SolverKind preferred_ = SolverKind::ConjugateGradient;
  bool decidedByShortfalls_ = false;
  int rounds_ = 0;
};

}  // namespace tetskin
