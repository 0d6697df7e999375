// SPDX-License-Identifier: AGPL-3.0-or-later
// The run layer: a session steps as the simulation and scenario wired by
// hand do, starts from a frame, keeps the step log, pulls, and records a
// series with its bound surface.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>
#include <string>

#include "BlockRun.h"
#include "ExpectError.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceFields.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

using test::blockWobble;
using test::uprightBlock;

TEST(SimulationSession, StepsAsTheSimulationAndScenarioWiredByHand) {
  const MultiLevelTetMesh mesh = uprightBlock();
  const RunSpec spec = blockWobble();
  SimulationSession session(mesh, spec);

  const TetMesh rest = extractLevel(mesh, 0);
  Simulation byHand(mesh, 0, scenarioOptions(spec.scenario, spec.options, rest), "block");
  auto scenario = makeScenario(spec.scenario, spec.parameters);
  scenario->setUp(byHand);

  EXPECT_EQ(session.state().positions, byHand.state().positions);
  for (int i = 0; i < 5; ++i) {
    session.step();
    scenario->beforeStep(byHand, byHand.time());
    byHand.step();
  }
  EXPECT_EQ(session.simulation().steps(), 5);
  EXPECT_DOUBLE_EQ(session.state().time, byHand.state().time);
  EXPECT_EQ(session.state().positions, byHand.state().positions);
  EXPECT_GT((session.state().positions - rest.nodes).norm(), 0);  // the push moved it
  EXPECT_STREQ(session.scenario().name(), "wobble");
  EXPECT_GT(session.lastStepSeconds(), 0);
}

TEST(SimulationSession, RefusesAnUnknownScenarioAndALevelTheDatasetLacks) {
  const MultiLevelTetMesh mesh = uprightBlock();
  RunSpec spec = blockWobble();
  spec.scenario = "spin";
  EXPECT_THROW(SimulationSession(mesh, spec), Error);
  spec = blockWobble();
  spec.level = 3;
  EXPECT_THROW(SimulationSession(mesh, spec), Error);
}

TEST(SimulationSession, PulledNodesMoveTheWayTheyArePulled) {
  const MultiLevelTetMesh mesh = uprightBlock();
  RunSpec spec = blockWobble();
  spec.scenario = "sag";
  spec.options.gravity.setZero();
  SimulationSession still(mesh, spec), pulled(mesh, spec);
  const Index top = mesh.nodes.rows() - 1;  // a corner of the top
  Points3 pull = Points3::Zero(mesh.nodes.rows(), 3);
  pull(top, 0) = 5;
  for (int i = 0; i < 3; ++i) {
    still.step();
    pulled.step(&pull);
  }
  EXPECT_NEAR((still.state().positions - mesh.nodes).norm(), 0, 1e-12);
  EXPECT_GT(pulled.state().positions(top, 0) - mesh.nodes(top, 0), 1e-6);
}

TEST(SimulationSession, StartsFromAFrameAndLogsFromThere) {
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationSession session(mesh, blockWobble());
  session.keepStepLog();
  ASSERT_EQ(session.stepLog().size(), 1u);
  session.step();
  EXPECT_EQ(session.stepLog().size(), 2u);

  FrameState start;
  start.positions = mesh.nodes;
  start.positions.col(0).array() += 0.01;  // shifted: no strain
  start.velocities = Points3::Zero(mesh.nodes.rows(), 3);
  start.velocities.col(2).setConstant(0.5);
  session.startFrom(start);
  EXPECT_EQ(session.state().positions, start.positions);
  EXPECT_EQ(session.state().velocities, start.velocities);
  ASSERT_EQ(session.stepLog().size(), 1u);  // the log begins again at the new start
  EXPECT_NEAR(session.stepLog()[0].kinetic, 0.5 * session.simulation().nodeMasses().sum() * 0.25,
              1e-12);
  session.step();
  session.step();
  ASSERT_EQ(session.stepLog().size(), 3u);
  EXPECT_EQ(session.stepLog()[2].step, session.simulation().steps());
  EXPECT_FALSE(session.stepLog()[2].solver.empty());
  EXPECT_GT(session.stepLog()[2].iterations, 0);
}

// "Run N steps, recording every k-th": the session's, for the command line
// (run: every k-th and the last) and for Python (stepRecordingEvery: every
// k-th of the whole run, however it is stepped).
TEST(SimulationSession, RecordsEveryKthStep) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationSession session(mesh, blockWobble());
  session.record(dir / "run.pvd");
  session.run(7, 3);  // steps 3, 6 and the last, 7
  EXPECT_EQ(session.recorder()->frames(), 3);
  SimulationSession stepped(mesh, blockWobble());
  stepped.record(dir / "stepped.pvd");
  for (int call = 0; call < 4; ++call)  // 4 calls of 2 steps: steps 3 and 6
    for (int i = 0; i < 2; ++i) stepped.stepRecordingEvery(3);
  EXPECT_EQ(stepped.recorder()->frames(), 2);
  EXPECT_EQ(stepped.simulation().steps(), 8);
}

TEST(SimulationSession, RecordsTheRunWithItsBoundSurface) {
  const test::ScratchDir dir;
  const MultiLevelTetMesh mesh = uprightBlock();
  SimulationSession session(mesh, blockWobble());
  EXPECT_THROW(session.recordFrame(), Error);  // nothing to record to
  EXPECT_THROW(session.deformedSurface(mesh.nodes), Error);

  const SurfaceMesh skin = test::box({-0.01, -0.01, -0.01}, {0.21, 0.41, 0.21});
  session.bindSurface(skin, bindSurface(skin, mesh, 0), "block.json");
  ASSERT_TRUE(session.hasSurface());
  // At rest the bound surface is where it was bound.
  EXPECT_LT((session.deformedSurface(mesh.nodes).deformed->positions - skin.positions)
                .cwiseAbs()
                .maxCoeff(),
            1e-12);

  session.record(dir / "run.pvd");
  ASSERT_TRUE(session.recording());
  session.recordFrame();
  for (int i = 0; i < 4; ++i) session.step();
  session.recordFrame();
  EXPECT_EQ(session.recorder()->frames(), 2);
  session.stopRecording();
  EXPECT_FALSE(session.recording());

  const RecordedRun run(dir / "run.pvd");
  ASSERT_EQ(run.frameCount(), 2u);
  EXPECT_EQ(run.level(), 0);
  ASSERT_TRUE(run.surfaceFile().has_value());
  // Its surface frames moved with the control mesh.
  const BoundSurface last = readBinding(dir / "run_frames" / "surface_00001.vtp");
  ASSERT_TRUE(last.deformed.has_value());
  EXPECT_GT((last.deformed->positions - skin.positions).norm(), 1e-6);
  // The skin carries the frame's stress and strain: each vertex the
  // binding-weighted, volume-weighted node means of its control frame's
  // element values (SurfaceFields.h), as the .vtu beside it has them.
  const vtkSmartPointer<vtkPolyData> surfaceFrame =
      readVtp(dir / "run_frames" / "surface_00001.vtp");
  const vtkSmartPointer<vtkUnstructuredGrid> controlFrame =
      readVtu(dir / "run_frames" / "control_00001.vtu");
  const TetMesh rest = extractLevel(mesh, 0);
  for (const char* name : {arrays::kVonMisesStress, arrays::kEquivalentStrain}) {
    vtkDataArray* cells = controlFrame->GetCellData()->GetArray(name);
    vtkDataArray* points = surfaceFrame->GetPointData()->GetArray(name);
    ASSERT_NE(cells, nullptr) << name;
    ASSERT_NE(points, nullptr) << name;
    Eigen::VectorXd perElement(rest.elementCount());
    for (Index e = 0; e < rest.elementCount(); ++e) perElement[e] = cells->GetTuple1(e);
    ASSERT_GT(perElement.maxCoeff(), 0) << name;
    const Eigen::VectorXd expected = boundValues(last.binding, 0, nodeMeans(rest, perElement));
    ASSERT_EQ(points->GetNumberOfTuples(), expected.size()) << name;
    for (Index v = 0; v < expected.size(); ++v)
      EXPECT_NEAR(points->GetTuple1(v), expected[v], 1e-12 * perElement.maxCoeff()) << name << v;
  }
}

}  // namespace
}  // namespace tetskin
