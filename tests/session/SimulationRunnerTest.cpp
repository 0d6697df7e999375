// SPDX-License-Identifier: AGPL-3.0-or-later
// A run on its own thread, used as tetskin-gui uses it: while the runner
// steps, another thread reads the state, computes the frame's fields,
// pulls, records and rebinds. The ThreadSanitizer build runs these (issue
// #53): a race between the stepping thread and the reading one fails
// them there.
#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

#include "BlockRun.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/session/SimulationRunner.h"
#include "tetskin/vtkio/RecordedRun.h"

namespace tetskin {
namespace {

using Clock = std::chrono::steady_clock;

using test::blockWobble;
using test::uprightBlock;

// Waits (at most a minute) until the runner has taken `steps` steps.
bool waitForSteps(const SimulationRunner& runner, Index steps) {
  const auto deadline = Clock::now() + std::chrono::minutes(1);
  while (runner.steps() < steps) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

TEST(SimulationRunner, StepsOnItsThreadWhileAnotherReadsPullsRecordsAndRebinds) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationRunner runner(mesh, blockWobble(), SimulationRunner::Pace::Unpaced);
  const SurfaceMesh skin = test::sphere({0.1, 0.2, 0.1}, 0.12, 8, 12);
  runner.session().bindSurface(skin, bindSurface(skin, mesh, 0), "block.json");
  runner.session().record(dir / "run.pvd");

  runner.play();
  const Index top = mesh.nodes.rows() - 1;
  Index seen = 0;
  int reads = 0;
  const auto deadline = Clock::now() + std::chrono::minutes(1);
  while ((runner.steps() < 60 || reads < 20) && Clock::now() < deadline) {
    // What the GUI's timer does between two drawings.
    const SimulationState state = runner.state();
    ASSERT_TRUE(state.positions.allFinite());
    ASSERT_GE(state.steps, seen);
    seen = state.steps;
    const FrameFields fields = runner.simulation().frameFields(state);
    ASSERT_TRUE(fields.vonMisesStress.allFinite());
    runner.session().recordFrame(state);
    ++reads;
    if (reads % 2 == 0) {
      runner.pull({static_cast<int>(top)}, Points3::Constant(1, 3, 0.5));
    } else {
      runner.release();
    }
    if (reads % 5 == 0) {
      BindingOptions options;
      options.method = reads % 10 == 0 ? BindingMethod::Closest : BindingMethod::Seed;
      runner.session().bindSurface(skin, bindSurface(skin, mesh, 0, options), "block.json");
    }
  }
  runner.pause();
  ASSERT_GE(runner.steps(), 60) << "the runner stalled";
  EXPECT_GE(reads, 20);
  EXPECT_FALSE(runner.takeFailure().has_value());

  // Paused, it stops after the step under way; step() takes one more.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const Index paused = runner.steps();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(runner.steps(), paused);
  runner.step();
  EXPECT_EQ(runner.steps(), paused + 1);

  const Index recorded = runner.session().recorder()->frames();
  runner.session().stopRecording();
  EXPECT_EQ(RecordedRun(dir / "run.pvd").frameCount(), static_cast<std::size_t>(recorded));
}

TEST(SimulationRunner, RealTimePaceKeepsSimulatedTimeBehindTheClock) {
  const MultiLevelTetMesh mesh = uprightBlock();
  const double timeStep = 0.02;
  SimulationRunner runner(mesh, blockWobble(timeStep));
  const auto start = Clock::now();
  runner.play();
  ASSERT_TRUE(waitForSteps(runner, 5));
  runner.pause();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  // Steps come no faster than one a time step: at most one beyond the clock.
  EXPECT_LE(static_cast<double>(runner.steps()) * timeStep, elapsed + timeStep);
}

TEST(SimulationRunner, AFailedStepPausesKeepsTheLastStateAndIsReportedOnce) {
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationRunner runner(mesh, blockWobble(), SimulationRunner::Pace::Unpaced);
  runner.step();
  const SimulationState good = runner.state();
  // A pull of NaN on a free node (the top's corner: the wobble holds the
  // base) makes the next step fail: the simulation refuses a non-finite state.
  const int top = static_cast<int>(mesh.nodes.rows() - 1);
  runner.pull({top}, Points3::Constant(1, 3, std::numeric_limits<double>::quiet_NaN()));
  runner.play();
  const auto deadline = Clock::now() + std::chrono::minutes(1);
  while (runner.playing() && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_FALSE(runner.playing());
  const std::optional<std::string> failure = runner.takeFailure();
  ASSERT_TRUE(failure.has_value());
  EXPECT_FALSE(failure->empty());
  EXPECT_FALSE(runner.takeFailure().has_value());
  EXPECT_EQ(runner.state().positions, good.positions);
}

}  // namespace
}  // namespace tetskin
