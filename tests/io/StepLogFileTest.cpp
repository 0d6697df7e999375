// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include "TestFiles.h"
#include "tetskin/io/StepLogFile.h"

namespace tetskin {
namespace {

// The start row leaves the step's columns empty; times are milliseconds;
// the total is the sum of the three energies; the reactions come last.
TEST(StepLogFile, WritesTheStartAndEachStep) {
  const test::ScratchDir dir;
  StepLogRow start;
  start.kinetic = 0;
  start.elastic = 0.5;
  StepLogRow step;
  step.step = 1;
  step.time = 0.25;
  step.solver = "multigrid";
  step.iterations = 7;
  step.residual = 8.5e-7;
  step.contacts = 3;
  step.assemblySeconds = 0.002;
  step.setupSeconds = 0.0005;
  step.solveSeconds = 0.004;
  step.stepSeconds = 0.0075;
  step.kinetic = 1.5;
  step.elastic = 2;
  step.gravitational = -0.25;
  step.load = -0.5;
  step.reaction = {0.5, 1962, -3e-9};
  writeStepLog(dir / "log.csv", {start, step});
  EXPECT_EQ(test::readText(dir / "log.csv"),
            stepLogHeader() +
                "\n"
                "0,0,,,,,,,,,0,0.5,0,0,0.5,0,0,0\n"
                "1,0.25,multigrid,7,8.5e-07,3,2,0.5,4,7.5,1.5,2,-0.25,-0.5,2.75,0.5,1962,-3e-09\n");
}

}  // namespace
}  // namespace tetskin
