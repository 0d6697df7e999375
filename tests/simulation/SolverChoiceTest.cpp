// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/simulation/SolverChoice.h"

namespace tetskin {
namespace {

using Kind = SolverKind;
constexpr Kind C = Kind::ConjugateGradient, M = Kind::Multigrid;

// Runs `steps` steps, each taking the time `seconds(kind, step)` and
// reaching the tolerance where `reached(kind, step)`; a step over its
// budget is cut off there, as SolverStack does. Returns the solver of
// every step.
template <typename Seconds, typename Reached>
std::vector<Kind> run(SolverChoice& choice, int steps, Seconds seconds, Reached reached) {
  std::vector<Kind> used;
  for (int i = 0; i < steps; ++i) {
    const SolverChoice::Turn turn = choice.next();
    used.push_back(turn.solver);
    const double t = seconds(turn.solver, i);
    const bool cut = t > turn.budgetSeconds;
    choice.record(cut ? turn.budgetSeconds : t, !cut && reached(turn.solver, i), cut);
  }
  return used;
}

// Every solve reaching the tolerance.
template <typename Seconds>
std::vector<Kind> run(SolverChoice& choice, int steps, Seconds seconds) {
  return run(choice, steps, seconds, [](Kind, int) { return true; });
}

TEST(SolverChoice, StartsWithMultigridAndSamplesCgWithinABudget) {
  SolverChoice choice(10);
  std::vector<double> budgets;
  const std::vector<Kind> used = run(choice, 30, [&](Kind kind, int) {
    if (kind == C) budgets.push_back(choice.next().budgetSeconds);
    return kind == M ? 0.010 : 0.025;
  });
  std::vector<Kind> expected(30, M);
  for (int sample : {2, 4, 14, 24}) expected[static_cast<std::size_t>(sample)] = C;
  EXPECT_EQ(used, expected);
  EXPECT_EQ(choice.preferred(), M);
  EXPECT_EQ(choice.samples(), 4);
  EXPECT_EQ(choice.cutOffSamples(), 4);  // CG's 0.025 s over its 0.0095 s budget
  EXPECT_EQ(choice.switches(), 0);
  for (double budget : budgets) EXPECT_DOUBLE_EQ(budget, SolverChoice::kWinningShare * 0.010);
}

TEST(SolverChoice, TwoWinningSamplesInARowMakeTheChallengerPreferred) {
  SolverChoice choice(10);
  const std::vector<Kind> used =
      run(choice, 20, [](Kind kind, int) { return kind == M ? 0.020 : 0.010; });
  // Multigrid for steps 0-1 and 3, CG's winning samples at 2 and 4; then
  // CG, with multigrid's sample at 14 (lost).
  const std::vector<Kind> expected{M, M, C, M, C, C, C, C, C, C, C, C, C, C, M, C, C, C, C, C};
  EXPECT_EQ(used, expected);
  EXPECT_EQ(choice.preferred(), C);
  EXPECT_EQ(choice.switches(), 1);
  EXPECT_FALSE(choice.decidedByShortfalls());
}

TEST(SolverChoice, FollowsAChangeOfRegimeAndConfirmsAWinTwoStepsLater) {
  // CG is faster for the first 40 steps, multigrid after.
  SolverChoice choice(10);
  const std::vector<Kind> used = run(choice, 60, [](Kind kind, int step) {
    const bool cgFaster = step < 40;
    return (kind == C) == cgFaster ? 0.01 : 0.02;
  });
  // CG preferred from step 5; multigrid's samples at 14, 24, 34 lose, at
  // 44 and (confirming) 46 win: multigrid from step 47.
  for (int i : {5, 15, 39, 43, 45}) EXPECT_EQ(used[static_cast<std::size_t>(i)], C) << i;
  for (int i : {44, 46, 47, 59}) EXPECT_EQ(used[static_cast<std::size_t>(i)], M) << i;
  EXPECT_EQ(choice.preferred(), M);
  EXPECT_EQ(choice.switches(), 2);
}

TEST(SolverChoice, AWinMustBeClearAndTheFirstStepIsNotTimed) {
  // CG 3% faster: within the margin, multigrid stays. A one-time cost in
  // multigrid's first step (its streams) does not count.
  SolverChoice choice(10);
  run(choice, 40, [](Kind kind, int step) {
    if (step == 0) return 100.0;
    return kind == M ? 0.0100 : 0.0097;
  });
  EXPECT_EQ(choice.preferred(), M);
  EXPECT_EQ(choice.switches(), 0);
}

TEST(SolverChoice, AnUntimedStepCountsAsSlow) {
  SolverChoice choice(10);
  run(choice, 10,
      [](Kind kind, int) { return kind == C ? std::numeric_limits<double>::quiet_NaN() : 1.0; });
  EXPECT_EQ(choice.preferred(), M);
}

TEST(SolverChoice, ASampleShortOfTheToleranceLosesWhateverItsTime) {
  // CG quicker, but at the iteration limit (a nearly incompressible body).
  SolverChoice choice(10);
  run(
      choice, 20, [](Kind kind, int) { return kind == M ? 0.05 : 0.02; },
      [](Kind kind, int) { return kind == M; });
  EXPECT_EQ(choice.preferred(), M);
  EXPECT_EQ(choice.switches(), 0);
}

TEST(SolverChoice, APreferredShortOfTheToleranceTwiceGivesWay) {
  // Multigrid stops short from step 10 on. CG's samples so far were cut
  // off; its next one (step 14) runs without a budget while the preferred
  // stops short, and reaches the tolerance, slower: CG takes over at
  // multigrid's next short step.
  SolverChoice choice(10);
  run(
      choice, 20, [](Kind kind, int) { return kind == M ? 0.01 : 0.03; },
      [](Kind kind, int step) { return kind == C || step < 10; });
  EXPECT_EQ(choice.preferred(), C);
  EXPECT_TRUE(choice.decidedByShortfalls());
}

TEST(SolverChoice, ShortfallsCountOverTheLastStepsNotOnlyInARow) {
  // CG preferred (faster), but short of the tolerance on every third step;
  // multigrid's samples, slower, reach it: multigrid takes over.
  SolverChoice choice(10);
  run(
      choice, 30, [](Kind kind, int) { return kind == M ? 0.02 : 0.01; },
      [](Kind kind, int step) { return kind == M || step < 10 || step % 3 != 0; });
  EXPECT_EQ(choice.preferred(), M);
  EXPECT_TRUE(choice.decidedByShortfalls());
}

TEST(SolverChoice, RefusesAnEmptyPeriod) {
  EXPECT_THROW(SolverChoice(0), Error);
}

TEST(SolverChoice, SolverNamesRoundTrip) {
  for (Kind kind : {Kind::ConjugateGradient, Kind::Multigrid, Kind::Automatic})
    EXPECT_EQ(fromName<SolverKind>(toString(kind)), kind);
  EXPECT_STREQ(toString(Kind::Automatic), "auto");
  EXPECT_THROW(fromName<SolverKind>("gmres"), Error);
  for (CoarseOperators kind : {CoarseOperators::Galerkin, CoarseOperators::Rediscretized})
    EXPECT_EQ(fromName<CoarseOperators>(toString(kind)), kind);
  for (CoarseLevels levels : {CoarseLevels::Grid, CoarseLevels::Dataset})
    EXPECT_EQ(fromName<CoarseLevels>(toString(levels)), levels);
  for (Tangent tangent : {Tangent::Full, Tangent::Warped})
    EXPECT_EQ(fromName<Tangent>(toString(tangent)), tangent);
}

// SimulationOptions' defaults are the schema's, and each is in its range.
TEST(SolverChoice, SimulationOptionDefaultsAreTheSchemas) {
  using namespace simulation_option;
  const SimulationOptions o;
  EXPECT_EQ(o.timeStep, kTimeStep.defaultValue);
  EXPECT_EQ(o.tolerance, kTolerance.defaultValue);
  EXPECT_EQ(o.guessSolutions, kGuessSolutions.defaultValue);
  EXPECT_EQ(o.coarseReuse, kCoarseReuse.defaultValue);
  EXPECT_EQ(o.maxIterations, kMaxIterations.defaultValue);
  EXPECT_EQ(o.friction, kFriction.defaultValue);
  EXPECT_EQ(o.floorStiffness, kFloorStiffness.defaultValue);
  for (const NumberOption* option : {&kTimeStep, &kTolerance, &kGuessSolutions, &kCoarseReuse,
                                     &kMaxIterations, &kFriction, &kFloorStiffness})
    EXPECT_FALSE(option->problem(option->defaultValue)) << option->key;
  EXPECT_EQ(*kTolerance.problem(1),
            "the solver tolerance (a relative residual) must lie in (0, 1), got 1");
}

// ScenarioParameters' defaults are the schema's, and each is in its range.
TEST(SolverChoice, ScenarioParameterDefaultsAreTheSchemas) {
  using namespace scenario_option;
  const ScenarioParameters p;
  for (const auto& [option, value] :
       {std::pair{&kBaseShare, p.baseShare}, std::pair{&kPushAcceleration, p.pushAcceleration},
        std::pair{&kPushFrequency, p.pushFrequency}, std::pair{&kDropHeight, p.dropHeight},
        std::pair{&kTwistDegrees, p.twistDegrees}, std::pair{&kTwistSeconds, p.twistSeconds}}) {
    EXPECT_EQ(value, option->defaultValue) << option->key;
    EXPECT_FALSE(option->problem(value)) << option->key;
  }
}

}  // namespace
}  // namespace tetskin
