// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The automatic solver: which of block-Jacobi CG and multigrid CG solves a
// simulation's steps faster, found by timing both on the running simulation.
//
// Neither wins everywhere: a multigrid iteration costs several CG iterations
// and its coarse operators cost a setup, so CG is faster on small or soft
// bodies (fewer CG iterations) and multigrid on large or stiff ones; where
// the two cross depends on the mesh, the material, the motion and the
// machine (doc/benchmarks.md: solver_bench). So one solver, the preferred,
// solves the steps, and the other, the challenger, solves a sample step now
// and then: steps 2 and 4, then one in every `period`, so that the
// samples spread over the run and a change of regime (a body coming to
// rest, a stiffer contact) is followed. A sample has a budget: the
// preferred's median time over its last steps, less the margin the
// challenger must win by. After a win the next sample comes two steps
// later, to confirm it. A challenger that runs out of it is cut off (its
// solve stops; the preferred finishes the step from where it got), so a
// losing sample costs at most about one step more, however slow the
// challenger would have been (CG on a stiff body takes 4x as long as the
// multigrid at 109k elements, and most in the first steps). Two samples in a
// row within budget make the challenger the preferred.
//
// Multigrid starts as the preferred: it is never far from the faster one,
// where CG can be many times slower. Its first step is not timed: it
// carries one-time costs (the Galerkin streams, the first allocations).
// Both solve every step to the same tolerance, so the choice moves the
// trajectory by no more than the solves' tolerance does, except where a
// solve stops at the iteration limit short of it (CG on a nearly
// incompressible body, nu = 0.4999): its step is then inexact and its time
// says nothing about the time to reach the tolerance. So a sample short of
// the tolerance loses, and a preferred that stopped short in two of its
// last 8 steps gives way to a challenger whose last sample reached it,
// whatever the times (while the preferred stops short, samples run
// without a budget), and comes back only when the other stops short in
// turn.

#include <string>
#include <vector>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

enum class SolverKind { ConjugateGradient, Multigrid, Automatic };
template <>
struct EnumSchema<SolverKind> {
  static constexpr const char* what = "solver";
  static constexpr EnumValue<SolverKind> values[] = {
      {SolverKind::Automatic, "auto", "whichever of the two is faster here, re-checked as it runs"},
      {SolverKind::ConjugateGradient, "cg", "block-Jacobi CG"},
      {SolverKind::Multigrid, "multigrid", "CG with a V-cycle"}};
};

class SolverChoice {
 public:
  // Samples after the first ones: one in every `period` steps.
  explicit SolverChoice(int period);

  struct Turn {
    SolverKind solver = SolverKind::Multigrid;  // ConjugateGradient or Multigrid
    bool sample = false;                        // the challenger's sample step
    // Seconds the step may take (setup and solve) before it is cut off;
    // infinite for the preferred's steps.
    double budgetSeconds = 0;
  };
  // The coming step's solver.
  Turn next() const;
  // How the step of next() went: its time (setup and solve, the setup
  // amortized as the solver would amortize it over a run), whether it
  // reached the tolerance, and whether it was cut off at its budget.
  void record(double seconds, bool reachedTolerance, bool cutOff);

  // The solver that solves the steps now.
  SolverKind preferred() const { return preferred_; }
  // Whether the last change of preferred was made by solves short of the
  // tolerance rather than by times.
  bool decidedByShortfalls() const { return decidedByShortfalls_; }
  // Samples taken, and how many of them were cut off.
  int samples() const { return samples_; }
  int cutOffSamples() const { return cutOffSamples_; }
  // Changes of preferred.
  int switches() const { return switches_; }

  // The share of the preferred's median a sample must stay under to count
  // as a win.
  static constexpr double kWinningShare = 0.95;

 private:
  bool isSampleStep(int step) const;
  double preferredMedian() const;
  int shortfalls() const;  // among the preferred's last steps
  void makeChallengerPreferred(bool byShortfalls);

  int period_;
  int step_ = 0;
  int lastSample_ = -1;  // the step of the last sample
  SolverKind preferred_ = SolverKind::Multigrid;
  std::vector<double> preferredTimes_;  // its last full steps (at most kWindow)
  std::vector<char> recentShortfalls_;  // its last steps (at most kWindow): 1 = short
  std::vector<double> challengerWins_;  // the challenger's last samples in a row within budget
  bool challengerLastReached_ = false;  // its last sample reached the tolerance
  bool decidedByShortfalls_ = false;
  int samples_ = 0, cutOffSamples_ = 0, switches_ = 0;
  static constexpr std::size_t kWindow = 8;
};

}  // namespace tetskin
