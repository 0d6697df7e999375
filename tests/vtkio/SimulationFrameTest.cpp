// SPDX-License-Identifier: AGPL-3.0-or-later
// Simulation frames read back (simulate --initial): the state written comes
// back exactly, a frame of another body is refused by name, and a run
// started from a frame goes on as the run that wrote it.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ExpectError.h"
#include "Frames.h"
#include "SampleData.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

using test::expectErrorAt;

struct Frame {
  TetMesh rest = test::tetGrid(2, 2, 2, Eigen::Vector3d(1, 2, 1));
  Points3 positions, velocities;
  Frame() {
    positions = rest.nodes;
    velocities = Points3::Zero(rest.nodeCount(), 3);
    for (Index v = 0; v < rest.nodeCount(); ++v) {
      const auto x = static_cast<double>(v);
      positions(v, 0) += 0.1 * std::sin(1.7 * x);
      velocities.row(v) << 0.3 * x, -1.0 / (x + 1), std::cos(x);
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid() const {
    return simulationFrame(rest, test::unloadedFrame(rest, positions, velocities), 0);
  }
};

TEST(SimulationFrame, StateComesBackExactly) {
  const test::ScratchDir dir;
  const Frame f;
  writeVtu(dir / "f.vtu", f.grid());
  const FrameState state = readSimulationFrame(dir / "f.vtu", f.rest, "the grid");
  EXPECT_EQ(state.positions, f.positions);
  EXPECT_EQ(state.velocities, f.velocities);
}

TEST(SimulationFrame, AFrameOfAnotherBodyIsRefusedByName) {
  const test::ScratchDir dir;
  const Frame f;
  const std::string file = (dir / "f.vtu").string();
  writeVtu(file, f.grid());
  const auto read = [&](const TetMesh& rest) {
    return [&] { readSimulationFrame(file, rest, "level 0 of b.json"); };
  };
  const TetMesh finer = test::tetGrid(3, 2, 2, Eigen::Vector3d(1, 2, 1));
  expectErrorAt(read(finer), file, 0,
                "has " + std::to_string(f.rest.nodeCount()) + " points and " +
                    std::to_string(f.rest.elementCount()) + " tetrahedra; level 0 of b.json has " +
                    std::to_string(finer.nodeCount()) + " and " +
                    std::to_string(finer.elementCount()));
  TetMesh renumbered = f.rest;
  renumbered.elements.row(5).swap(renumbered.elements.row(6));
  expectErrorAt(read(renumbered), file, 0,
                "tetrahedron 5 has other nodes than in level 0 of b.json");
  TetMesh moved = f.rest;
  moved.nodes(3, 1) += 1e-6;
  expectErrorAt(read(moved), file, 0,
                "point 3: its position less its Displacement is not its rest position in level 0 "
                "of b.json");

  vtkSmartPointer<vtkUnstructuredGrid> grid = f.grid();
  grid->GetPointData()->RemoveArray("Velocity");
  writeVtu(file, grid);
  expectErrorAt(read(f.rest), file, 0, "point array 'Velocity' is missing");
  grid = f.grid();
  vtkDoubleArray::SafeDownCast(grid->GetPointData()->GetArray("Velocity"))
      ->SetComponent(4, 2, std::numeric_limits<double>::quiet_NaN());
  writeVtu(file, grid);
  expectErrorAt(read(f.rest), file, 0, "Velocity of point 4 ");
}

// Each field of a frame goes into the array of its name (vectors per node,
// stresses per element) as it is; fields of another size than the level's
// are refused by name before anything is written.
TEST(SimulationFrame, EachFieldGoesIntoTheArrayOfItsName) {
  const Frame f;
  FrameFields fields = test::unloadedFrame(f.rest, f.positions, f.velocities);
  const Index nodes = f.rest.nodeCount(), elements = f.rest.elementCount();
  for (Index v = 0; v < nodes; ++v) {
    fields.externalForces.row(v) << 1.5 * static_cast<double>(v), 0, -2;
    fields.reactionForces.row(v) << 0, 0.25 * static_cast<double>(v), 7;
  }
  for (Index e = 0; e < elements; ++e) {
    fields.vonMisesStress[e] = 100.0 + static_cast<double>(e);
    fields.equivalentStrain[e] = 0.001 * static_cast<double>(e);
  }
  const vtkSmartPointer<vtkUnstructuredGrid> grid = simulationFrame(f.rest, fields, 2);
  const auto vectors = [&](const char* name) {
    vtkDataArray* array = grid->GetPointData()->GetArray(name);
    EXPECT_NE(array, nullptr) << name;
    Points3 rows(array ? array->GetNumberOfTuples() : 0, 3);
    for (Index v = 0; v < rows.rows(); ++v)
      for (int c = 0; c < 3; ++c) rows(v, c) = array->GetComponent(v, c);
    return rows;
  };
  EXPECT_EQ(vectors("Displacement"), f.positions - f.rest.nodes);
  EXPECT_EQ(vectors("Velocity"), fields.velocities);
  EXPECT_EQ(vectors("ExternalForce"), fields.externalForces);
  EXPECT_EQ(vectors("ReactionForce"), fields.reactionForces);
  vtkDataArray* stress = grid->GetCellData()->GetArray("VonMisesStress");
  ASSERT_NE(stress, nullptr);
  ASSERT_EQ(stress->GetNumberOfTuples(), elements);
  for (Index e = 0; e < elements; ++e) EXPECT_EQ(stress->GetTuple1(e), fields.vonMisesStress[e]);
  vtkDataArray* strain = grid->GetCellData()->GetArray("EquivalentStrain");
  ASSERT_NE(strain, nullptr);
  ASSERT_EQ(strain->GetNumberOfTuples(), elements);
  for (Index e = 0; e < elements; ++e) EXPECT_EQ(strain->GetTuple1(e), fields.equivalentStrain[e]);
  // The stress tensor, when the frame has one: six components in VTK's
  // order.
  EXPECT_EQ(grid->GetCellData()->GetArray("Stress"), nullptr);
  FrameFields stressed = fields;
  stressed.stress.resize(elements, 6);
  for (Index e = 0; e < elements; ++e)
    for (int c = 0; c < 6; ++c) stressed.stress(e, c) = 10.0 * static_cast<double>(e) + c;
  const vtkSmartPointer<vtkUnstructuredGrid> withStress = simulationFrame(f.rest, stressed, 2);
  vtkDataArray* tensors = withStress->GetCellData()->GetArray("Stress");
  ASSERT_NE(tensors, nullptr);
  ASSERT_EQ(tensors->GetNumberOfComponents(), 6);
  ASSERT_EQ(tensors->GetNumberOfTuples(), elements);
  for (Index e = 0; e < elements; ++e)
    for (int c = 0; c < 6; ++c) EXPECT_EQ(tensors->GetComponent(e, c), stressed.stress(e, c));
  stressed.stress.conservativeResize(elements - 1, 6);
  EXPECT_EQ(test::errorText([&] { simulationFrame(f.rest, stressed, 2); }),
            "the frame's stress tensors: " + std::to_string(elements - 1) + " rows for " +
                std::to_string(elements) + " elements");

  const std::string counts = std::to_string(nodes) + " nodes";
  FrameFields shortReactions = fields;
  shortReactions.reactionForces.conservativeResize(nodes - 1, 3);
  EXPECT_EQ(test::errorText([&] { simulationFrame(f.rest, shortReactions, 2); }),
            "the frame's reaction forces: " + std::to_string(nodes - 1) + " rows for " + counts);
  FrameFields noStresses = fields;
  noStresses.vonMisesStress.resize(0);
  EXPECT_EQ(test::errorText([&] { simulationFrame(f.rest, noStresses, 2); }),
            "the frame's stresses: 0 rows for " + std::to_string(elements) + " elements");
  FrameFields noStrains = fields;
  noStrains.equivalentStrain.resize(0);
  EXPECT_EQ(test::errorText([&] { simulationFrame(f.rest, noStrains, 2); }),
            "the frame's strains: 0 rows for " + std::to_string(elements) + " elements");
}

// A recorded run read back (render --run, deform --positions RUN.pvd, the
// GUI's replay): its control frames in time order whatever the .pvd's
// order, the surface's entries left out, the level its frames say; a
// series without control frames or with a frame file missing is refused,
// naming the .pvd.
TEST(RecordedRun, ReadsTheControlFramesInTimeOrder) {
  const test::ScratchDir dir;
  const Frame f;
  Points3 second = f.positions;
  second(2, 1) += 0.25;
  for (const char* name : {"a.vtu", "b.vtu"})
    writeVtu(dir / name,
             simulationFrame(
                 f.rest,
                 test::unloadedFrame(f.rest, std::string(name) == "a.vtu" ? f.positions : second,
                                     f.velocities),
                 3));
  PvdSeries series(dir / "run.pvd");
  series.add(0.5, 0, "b.vtu");
  series.add(0.5, 1, "surface.vtp");  // (not read)
  series.add(0.25, 0, "a.vtu");
  series.write();
  const RecordedRun run(dir / "run.pvd");
  ASSERT_EQ(run.frameCount(), 2u);
  EXPECT_EQ(run.time(0), 0.25);
  EXPECT_EQ(run.time(1), 0.5);
  EXPECT_EQ(run.level(), 3);
  EXPECT_EQ(run.surfaceFile(), (dir / "surface.vtp").string());
  EXPECT_EQ(run.read(0, f.rest, "the grid").positions, f.positions);
  EXPECT_EQ(run.read(1, f.rest, "the grid").positions, second);

  const std::string surfaces = (dir / "surfaces.pvd").string();
  PvdSeries onlySurfaces(surfaces);
  onlySurfaces.add(0, 1, "surface.vtp");
  onlySurfaces.write();
  expectErrorAt([&] { RecordedRun{surfaces}; }, surfaces, 0,
                "has no frames of part 0 (the control mesh)");
  const std::string gap = (dir / "gap.pvd").string();
  PvdSeries withGap(gap);
  withGap.add(0, 0, "a.vtu");
  withGap.add(1, 0, "gone/c.vtu");
  withGap.write();
  expectErrorAt([&] { RecordedRun{gap}; }, gap, 0,
                "names the frame gone/c.vtu, which is not there");
}

// A run's floor goes into its control frames as field data a ParaView user
// can read (the plane's normal and height), and comes back from them: the
// recorded run is drawn with it. A frame without it, or with a plane that
// is no axis' (not one this program simulates), has none.
TEST(RecordedRun, KeepsTheRunsFloor) {
  const test::ScratchDir dir;
  const Frame f;
  const FloorPlane floor{UpAxis::Z, -0.375};
  {
    RunRecorder recorder(dir / "run.pvd", RunConditions{floor, {}});
    recorder.addFrame(0, f.rest, test::unloadedFrame(f.rest, f.positions), 0);
  }
  EXPECT_EQ(RecordedRun(dir / "run.pvd").floor(), floor);
  const SimulationFrameFacts facts = simulationFrameFacts(dir / "run_frames/control_00000.vtu");
  EXPECT_EQ(facts.level, 0);
  EXPECT_EQ(facts.conditions.floor, floor);
  vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(dir / "run_frames/control_00000.vtu");
  const double* normal = grid->GetFieldData()->GetArray("FloorNormal")->GetTuple3(0);
  EXPECT_EQ(Eigen::Vector3d(normal[0], normal[1], normal[2]), Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(grid->GetFieldData()->GetArray("FloorHeight")->GetTuple1(0), -0.375);

  {
    RunRecorder recorder(dir / "plain.pvd");
    recorder.addFrame(0, f.rest, test::unloadedFrame(f.rest, f.positions), 0);
  }
  EXPECT_EQ(RecordedRun(dir / "plain.pvd").floor(), std::nullopt);

  grid->GetFieldData()->GetArray("FloorNormal")->SetTuple3(0, 0, 0.6, 0.8);
  writeVtu(dir / "tilted.vtu", grid);
  EXPECT_EQ(simulationFrameFacts(dir / "tilted.vtu").conditions.floor, std::nullopt);
  EXPECT_EQ(simulationFrameFacts(dir / "tilted.vtu").level, 0);
}

// The nodes a run prescribes go into its control frames as a 0/1 point
// array (ParaView thresholds by it) and come back from them, sorted; a run
// recorded before frames said has none. A node the mesh lacks is an error.
TEST(RecordedRun, KeepsTheRunsPrescribedNodes) {
  const test::ScratchDir dir;
  const Frame f;
  {
    RunRecorder recorder(dir / "run.pvd", RunConditions{std::nullopt, {7, 2, 5}});
    recorder.addFrame(0, f.rest, test::unloadedFrame(f.rest, f.positions), 0);
  }
  const RecordedRun run(dir / "run.pvd");
  EXPECT_EQ(run.prescribedNodes(), (std::vector<int>{2, 5, 7}));
  EXPECT_EQ(run.floor(), std::nullopt);
  vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(dir / "run_frames/control_00000.vtu");
  vtkDataArray* prescribed = grid->GetPointData()->GetArray("Prescribed");
  ASSERT_NE(prescribed, nullptr);
  ASSERT_EQ(prescribed->GetNumberOfTuples(), f.rest.nodeCount());
  for (vtkIdType v = 0; v < prescribed->GetNumberOfTuples(); ++v)
    EXPECT_EQ(prescribed->GetTuple1(v), v == 2 || v == 5 || v == 7 ? 1.0 : 0.0) << v;

  grid->GetPointData()->RemoveArray("Prescribed");
  writeVtu(dir / "older.vtu", grid);
  EXPECT_TRUE(simulationFrameFacts(dir / "older.vtu").conditions.prescribedNodes.empty());

  const int missing = static_cast<int>(f.rest.nodeCount());
  EXPECT_EQ(test::errorText([&] {
              simulationFrame(f.rest, test::unloadedFrame(f.rest, f.positions), 0,
                              RunConditions{std::nullopt, {missing}});
            }),
            "prescribed node " + std::to_string(missing) + " does not exist (the mesh has " +
                std::to_string(missing) + " nodes)");
}

// A run written under the name of an earlier, longer one replaces it: the
// earlier frames past the new run's last are gone (ParaView, opening the
// folder, would show them after the new ones), other files stay.
TEST(RunRecorder, ARunWrittenAgainReplacesTheEarlierFrames) {
  const test::ScratchDir dir;
  const Frame f;
  {
    RunRecorder first(dir / "run.pvd");
    for (int i = 0; i < 4; ++i)
      first.addFrame(i, f.rest, test::unloadedFrame(f.rest, f.positions), 0);
  }
  dir.write("run_frames/notes.txt", "mine");
  RunRecorder second(dir / "run.pvd");
  EXPECT_FALSE(std::filesystem::exists(dir / "run.pvd"));  // until its first frame
  for (int i = 0; i < 2; ++i)
    second.addFrame(i, f.rest, test::unloadedFrame(f.rest, f.positions), 0);
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "run_frames"))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files,
            (std::vector<std::string>{"control_00000.vtu", "control_00001.vtu", "notes.txt"}));
  EXPECT_EQ(RecordedRun(dir / "run.pvd").frameCount(), 2u);
}

// A sag run of 40 steps, and one of 20 steps started again from its 20th
// frame for 20 more: the same state to within the solver's tolerance
// (each solve stops at a relative residual of 1e-6), where the 20 steps
// from rest alone are far from it.
TEST(SimulationFrame, ARunStartedFromAFrameGoesOnAsTheRunThatWroteIt) {
  const Dataset& d = test::sampleDataset();
  SimulationOptions options;
  options.solver = SolverKind::ConjugateGradient;
  const auto run = [&](int steps, const FrameState* start) {
    Simulation sim(d.mesh, 0, options);
    makeScenario("sag", {})->setUp(sim);
    if (start) {
      sim.setPositions(start->positions);
      sim.setVelocities(start->velocities);
    }
    for (int i = 0; i < steps; ++i) sim.step();
    return sim.state();
  };
  const SimulationState whole = run(40, nullptr), half = run(20, nullptr);
  const test::ScratchDir dir;
  Simulation writer(d.mesh, 0, options);
  writeVtu(dir / "half.vtu", simulationFrame(writer.restMesh(), writer.frameFields(half), 0));
  const FrameState start = readSimulationFrame(dir / "half.vtu", writer.restMesh(), "level 0");
  const SimulationState resumed = run(20, &start);
  const double sag = (whole.positions - writer.restMesh().nodes).cwiseAbs().maxCoeff();
  const double resumedOff = (resumed.positions - whole.positions).cwiseAbs().maxCoeff();
  const double restartOff = (half.positions - whole.positions).cwiseAbs().maxCoeff();
  std::printf("largest displacement %.4g; resumed run off by %.3g, 20 steps from rest by %.3g\n",
              sag, resumedOff, restartOff);
  EXPECT_GT(restartOff, 0.05 * sag);
  EXPECT_LT(resumedOff, 1e-4 * sag);
}

}  // namespace
}  // namespace tetskin
