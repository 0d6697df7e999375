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

// Runs `steps` steps, each taking the time `seconds(kind, step)` and
// reaching the tolerance where `reached(kind, step)`, and returns the solver
// of every step.
template <typename Seconds, typename Reached>
std::vector<Kind> run(SolverChoice& choice, int steps, Seconds seconds, Reached reached) {
  std::vector<Kind> used;
  for (int i = 0; i < steps; ++i) {
    used.push_back(choice.next());
    choice.record(seconds(used.back(), i), reached(used.back(), i));
  }
  return used;
}

// Every solve reaching the tolerance.
template <typename Seconds>
std::vector<Kind> run(SolverChoice& choice, int steps, Seconds seconds) {
  return run(choice, steps, seconds, [](Kind, int) { return true; });
}

TEST(SolverChoice, AlternatesTheTrialsThenKeepsTheFasterUntilTheNextRound) {
  SolverChoice choice(3, 5);
  const std::vector<Kind> used = run(choice, 2 + 2 * (6 + 5), [](Kind kind, int) {
    return kind == Kind::Multigrid ? 0.010 : 0.025;
  });
  const Kind C = Kind::ConjugateGradient, M = Kind::Multigrid;
  const std::vector<Kind> expected{C, M,                              // untimed
                                   C, M, C, M, C, M, M, M, M, M, M,   // round 1
                                   C, M, C, M, C, M, M, M, M, M, M};  // round 2
  EXPECT_EQ(used, expected);
  EXPECT_EQ(choice.rounds(), 2);
  EXPECT_EQ(choice.preferred(), M);
}

TEST(SolverChoice, FollowsAChangeOfRegime) {
  // CG is faster for the first 22 steps, multigrid after.
  SolverChoice choice(2, 6);
  const std::vector<Kind> used = run(choice, 32, [](Kind kind, int step) {
    const bool cgFaster = step < 22;
    return (kind == Kind::ConjugateGradient) == cgFaster ? 0.01 : 0.02;
  });
  // Two untimed steps, then rounds of 4 trials + 6 steps: steps 6-11 and
  // 16-21 with CG, 26-31 (after the trials of 22-25) with multigrid.
  for (int i : {6, 11, 16, 21}) EXPECT_EQ(used[i], Kind::ConjugateGradient) << i;
  for (int i : {26, 31}) EXPECT_EQ(used[i], Kind::Multigrid) << i;
}

TEST(SolverChoice, ComparesTheTrialsTotalsNotSingleSteps) {
  // Multigrid's trials include one slow step (a coarse rebuild) in three:
  // 0.03 + 0.005 + 0.005 = 0.04 against CG's 3 x 0.012 = 0.036.
  SolverChoice choice(3, 10);
  int multigridStep = 0;
  run(choice, 2 + 6, [&](Kind kind, int step) {
    if (step < 2) return 1.0;  // untimed
    if (kind == Kind::ConjugateGradient) return 0.012;
    return multigridStep++ == 0 ? 0.03 : 0.005;
  });
  EXPECT_EQ(choice.preferred(), Kind::ConjugateGradient);
}

TEST(SolverChoice, AnUntimedStepCountsAsSlow) {
  SolverChoice choice(1, 4);
  run(choice, 2 + 2, [](Kind kind, int) {
    return kind == Kind::Multigrid ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  });
  EXPECT_EQ(choice.preferred(), Kind::ConjugateGradient);
}

TEST(SolverChoice, TheFirstTwoStepsAreNotTimed) {
  // A one-time cost in the first multigrid step (its streams) must not
  // decide the first round.
  SolverChoice choice(2, 4);
  run(choice, 2 + 4, [](Kind kind, int step) {
    if (step == 1) return 100.0;
    return kind == Kind::Multigrid ? 0.01 : 0.02;
  });
  EXPECT_EQ(choice.rounds(), 1);
  EXPECT_EQ(choice.preferred(), Kind::Multigrid);
}

TEST(SolverChoice, ASolverStoppingShortOfTheToleranceLosesWhateverItsTime) {
  // CG at the iteration limit in one of its three trials (a nearly
  // incompressible body): its steps were quicker, but not solved.
  SolverChoice choice(3, 10);
  run(
      choice, 2 + 6, [](Kind kind, int) { return kind == Kind::Multigrid ? 0.05 : 0.02; },
      [](Kind kind, int step) { return kind == Kind::Multigrid || step != 4; });
  EXPECT_EQ(choice.preferred(), Kind::Multigrid);
  EXPECT_TRUE(choice.decidedByShortfalls());
}

TEST(SolverChoice, TheTimesDecideBetweenSolversStoppingShortAlike) {
  SolverChoice choice(2, 10);
  run(
      choice, 2 + 4, [](Kind kind, int) { return kind == Kind::Multigrid ? 0.05 : 0.02; },
      [](Kind, int step) { return step != 2 && step != 3; });  // one short trial each
  EXPECT_EQ(choice.preferred(), Kind::ConjugateGradient);
  EXPECT_FALSE(choice.decidedByShortfalls());
}

TEST(SolverChoice, ShortSolvesCountOnlyInTheirRound) {
  // CG short in round 1 (multigrid preferred), then fine and faster in
  // round 2: CG again.
  SolverChoice choice(1, 3);
  run(
      choice, 2 + 2 * (2 + 3), [](Kind kind, int) { return kind == Kind::Multigrid ? 0.05 : 0.02; },
      [](Kind kind, int step) { return kind == Kind::Multigrid || step != 2; });
  EXPECT_EQ(choice.rounds(), 2);
  EXPECT_EQ(choice.preferred(), Kind::ConjugateGradient);
  EXPECT_FALSE(choice.decidedByShortfalls());
}

TEST(SolverChoice, TheUntimedStepsShortfallsDoNotCount) {
  SolverChoice choice(1, 3);
  run(
      choice, 2 + 2, [](Kind kind, int) { return kind == Kind::Multigrid ? 0.05 : 0.02; },
      [](Kind, int step) { return step >= 2; });
  EXPECT_EQ(choice.preferred(), Kind::ConjugateGradient);
}

TEST(SolverChoice, RefusesEmptyTrials) {
  EXPECT_THROW(SolverChoice(0, 10), Error);
  EXPECT_THROW(SolverChoice(2, -1), Error);
}

TEST(SolverChoice, SolverNamesRoundTrip) {
  for (Kind kind : {Kind::ConjugateGradient, Kind::Multigrid, Kind::Automatic})
    EXPECT_EQ(fromName<SolverKind>(toString(kind)), kind);
  EXPECT_STREQ(toString(Kind::Automatic), "auto");
  EXPECT_THROW(fromName<SolverKind>("gmres"), Error);
  for (CoarseOperators kind : {CoarseOperators::Galerkin, CoarseOperators::Rediscretized})
    EXPECT_EQ(fromName<CoarseOperators>(toString(kind)), kind);
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
