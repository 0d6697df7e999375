// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "ExpectError.h"
#include "SampleData.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

TEST(BindingFile, WriteThenReadIsExact) {
  test::ScratchDir dir;
  const Dataset& d = sampleDataset();
  for (BindingMethod method : {BindingMethod::Closest, BindingMethod::Embed}) {
    BoundSurface bound;
    bound.surface = readObj(kSampleData + "bunny.obj");
    BindingOptions options;
    options.method = method;
    options.offset = OffsetMode::Displacement;
    bound.binding = bindSurface(bound.surface, d.mesh, 1, options);
    bound.dataset = (dir / "data/bunny.json").string();
    writeBinding(dir / "b.vtp", bound);
    const BoundSurface back = readBinding(dir / "b.vtp");
    EXPECT_EQ(back.dataset, bound.dataset);
    EXPECT_EQ(back.binding.method, method);
    EXPECT_EQ(back.binding.offset, OffsetMode::Displacement);
    EXPECT_EQ(back.binding.level, 1);
    EXPECT_EQ(back.binding.controlIds, bound.binding.controlIds);
    EXPECT_EQ(back.binding.weights, bound.binding.weights);
    EXPECT_EQ(back.binding.distance, bound.binding.distance);
    EXPECT_EQ(back.binding.faceId, bound.binding.faceId);
    EXPECT_EQ(back.surface.positions, bound.surface.positions);
    EXPECT_EQ(back.surface.triangles, bound.surface.triangles);
  }
}

// A binding file names its dataset from its own folder, so that the two move
// together; read back, the name is a path from the working folder again.
TEST(BindingFile, ItsDatasetIsNamedFromItsOwnFolder) {
  test::ScratchDir dir;
  const Dataset& d = sampleDataset();
  BoundSurface bound;
  bound.surface = readObj(kSampleData + "bunny.obj");
  bound.binding = bindSurface(bound.surface, d.mesh, 1);
  bound.dataset = (dir / "data/bunny.json").string();
  std::filesystem::create_directories(dir / "runs/frames");
  const std::filesystem::path file = dir / "runs/frames/b.vtp";
  writeBinding(file, bound);
  EXPECT_EQ(bindingFromPolyData(readVtp(file), "b.vtp").dataset, "../../data/bunny.json");
  EXPECT_EQ(readBinding(file).dataset, (dir / "data/bunny.json").generic_string());
  EXPECT_EQ(readBinding(file, d.mesh).dataset, (dir / "data/bunny.json").generic_string());
  // From a relative file name, relative again; absolute names stay; none is none.
  EXPECT_EQ(datasetOfField("../../data/bunny.json", "runs/frames/b.vtp"), "data/bunny.json");
  EXPECT_EQ(datasetOfField("/data/bunny.json", "runs/b.vtp"), "/data/bunny.json");
  EXPECT_EQ(datasetField("", file), "");
  EXPECT_EQ(datasetOfField("", file), "");
}

// bunny.obj bound to `level` of `d` (closest), its dataset named bunny.json.
BoundSurface boundBunny(const Dataset& d, int level) {
  BoundSurface bound;
  bound.surface = readObj(kSampleData + "bunny.obj");
  bound.binding = bindSurface(bound.surface, d.mesh, level);
  bound.dataset = "bunny.json";
  return bound;
}

TEST(BindingFile, PlainSurfaceIsNotABinding) {
  test::ScratchDir dir;
  writeSurface(dir / "s.vtp", readObj(kSampleData + "bunny.obj"));
  try {
    readBinding(dir / "s.vtp");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("is not a TetSkin binding"), std::string::npos) << e.what();
  }
}

// Read for use with a dataset, a binding that does not fit it is an error
// naming the file: a level it lacks, nodes of another level, a broken weight.
TEST(BindingFile, BindingThatDoesNotFitTheDatasetIsNamed) {
  test::ScratchDir dir;
  const Dataset& d = sampleDataset();
  const BoundSurface good = boundBunny(d, 0);
  writeBinding(dir / "good.vtp", good);
  EXPECT_EQ(readBinding(dir / "good.vtp", d.mesh).binding.controlIds, good.binding.controlIds);
  auto error = [&](const std::function<void(BoundSurface&)>& spoil) -> std::string {
    BoundSurface bad = good;
    spoil(bad);
    writeBinding(dir / "bad.vtp", bad);
    try {
      readBinding(dir / "bad.vtp", d.mesh);
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), (dir / "bad.vtp").string());
      return e.message();
    }
    return "no error";
  };
  EXPECT_EQ(error([](BoundSurface& b) { b.binding.level = 7; }),
            "is bound to level 7, but the dataset has levels 0..2");
  const std::string otherLevel = error([](BoundSurface& b) { b.binding.level = 1; });
  EXPECT_EQ(otherLevel.rfind("vertex 0 is bound to node ", 0), 0u) << otherLevel;
  EXPECT_NE(otherLevel.find(", outside level 1's nodes [224, 1061) (a binding made for another "
                            "dataset?)"),
            std::string::npos)
      << otherLevel;
  EXPECT_EQ(error([](BoundSurface& b) { b.binding.weights(5, 1) = std::nan(""); }),
            "vertex 5 has a non-finite weight");
  EXPECT_EQ(error([](BoundSurface& b) { b.binding.controlIds(9, 2) = 99999; }),
            "vertex 9 is bound to node 99999, outside the dataset's 4331 nodes");
}

// What the applications open as a surface: a binding .vtp with its binding
// and the dataset it names (checked against a dataset when one is given),
// any other surface file without one, whatever point arrays it carries.
TEST(BindingFile, SurfaceOrBindingTellsABindingByItsFieldData) {
  test::ScratchDir dir;
  const Dataset& d = sampleDataset();
  BoundSurface bound = boundBunny(d, 1);
  writeBinding(dir / "bound.vtp", bound);
  const SurfaceOrBinding fromBinding = readSurfaceOrBinding(dir / "bound.vtp", d.mesh);
  ASSERT_TRUE(fromBinding.binding.has_value());
  EXPECT_EQ(fromBinding.binding->level, 1);
  EXPECT_EQ(fromBinding.binding->controlIds, bound.binding.controlIds);
  EXPECT_EQ(fromBinding.surface.positions, bound.surface.positions);
  const std::string named = readBinding(dir / "bound.vtp").dataset;
  EXPECT_NE(named, "");
  EXPECT_EQ(fromBinding.dataset, named);  // from the working folder, as readBinding names it
  // The binding arrays without the field data: a plain surface.
  vtkSmartPointer<vtkPolyData> arraysOnly = bindingToPolyData(bound);
  arraysOnly->GetFieldData()->Initialize();
  writeVtp(dir / "arrays.vtp", arraysOnly);
  writeSurface(dir / "plain.vtp", bound.surface);
  for (const char* name : {"arrays.vtp", "plain.vtp"}) {
    const SurfaceOrBinding plain = readSurfaceOrBinding(dir / name, d.mesh);
    EXPECT_FALSE(plain.binding.has_value()) << name;
    EXPECT_EQ(plain.dataset, "") << name;
    EXPECT_EQ(plain.surface.triangles, bound.surface.triangles) << name;
  }
  EXPECT_FALSE(readSurfaceOrBinding(kSampleData + "bunny.obj", d.mesh).binding.has_value());
  // A binding that does not fit the dataset is an error, as readBinding's.
  bound.binding.level = 7;
  writeBinding(dir / "bad.vtp", bound);
  EXPECT_THROW(readSurfaceOrBinding(dir / "bad.vtp", d.mesh), Error);
  // Read without a dataset (the GUI, to open the dataset it names first), it
  // is not checked.
  const SurfaceOrBinding unchecked = readSurfaceOrBinding(dir / "bad.vtp");
  ASSERT_TRUE(unchecked.binding.has_value());
  EXPECT_EQ(unchecked.binding->level, 7);
  EXPECT_EQ(unchecked.dataset, named);
}

// A surface the binding has moved (deform's output, simulate's frames, the
// GUI's export) is written at its moved points, with a Displacement array
// from rest and Pose "deformed"; read back, it is the whole binding again,
// at rest (its normals were not written), with the moved state beside it.
// Files from before the pose was written read as rest.
TEST(BindingFile, ADeformedSurfaceKeepsItsRestShape) {
  test::ScratchDir dir;
  const Dataset& d = sampleDataset();
  BoundSurface moved = boundBunny(d, 1);
  moved.binding.offset = OffsetMode::Displacement;  // (the offset that reads the rest shape)
  DeformedState state{moved.surface.positions, moved.surface.positions};
  state.positions.col(1).array() += 0.5;
  state.normals.rowwise() = Eigen::RowVector3d(0, 0, 1);
  moved.deformed = state;
  writeBinding(dir / "moved.vtp", moved);
  const vtkSmartPointer<vtkPolyData> file = readVtp(dir / "moved.vtp");
  EXPECT_TRUE(isDeformed(file, "moved.vtp"));
  EXPECT_EQ(fromVtkPoints(file->GetPoints(), "moved.vtp"), state.positions);
  const std::optional<Points3> displacement =
      fromVtkVectors(file->GetPointData()->GetArray("Displacement"));
  ASSERT_TRUE(displacement.has_value());
  EXPECT_LT((*displacement - (state.positions - moved.surface.positions)).cwiseAbs().maxCoeff(),
            1e-12);
  for (const BoundSurface& back :
       {readBinding(dir / "moved.vtp"), readBinding(dir / "moved.vtp", d.mesh)}) {
    ASSERT_TRUE(back.deformed.has_value());
    EXPECT_EQ(back.deformed->positions, state.positions);
    EXPECT_EQ(back.deformed->normals, state.normals);
    EXPECT_LT((back.surface.positions - moved.surface.positions).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_FALSE(back.surface.hasNormals());
    EXPECT_EQ(back.binding.controlIds, moved.binding.controlIds);
  }
  const SurfaceOrBinding opened = readSurfaceOrBinding(dir / "moved.vtp", d.mesh);
  ASSERT_TRUE(opened.binding.has_value());
  EXPECT_LT((opened.surface.positions - moved.surface.positions).cwiseAbs().maxCoeff(), 1e-12);

  // Without its Displacement array a deformed file has lost its rest shape.
  vtkSmartPointer<vtkPolyData> lost = bindingToPolyData(moved);
  lost->GetPointData()->RemoveArray("Displacement");
  writeVtp(dir / "lost.vtp", lost);
  EXPECT_EQ(test::errorText([&] { readBinding(dir / "lost.vtp", d.mesh); }),
            (dir / "lost.vtp").string() +
                ": is a deformed surface (field data Pose 'deformed') without its rest shape: "
                "point array 'Displacement' is missing or has the wrong size");

  BoundSurface rest = boundBunny(d, 1);
  vtkSmartPointer<vtkPolyData> data = bindingToPolyData(rest);
  EXPECT_FALSE(isDeformed(data, "rest"));
  EXPECT_EQ(data->GetPointData()->GetArray("Displacement"), nullptr);
  data->GetFieldData()->RemoveArray("Pose");  // as written before the pose was
  writeVtp(dir / "old.vtp", data);
  EXPECT_FALSE(readBinding(dir / "old.vtp", d.mesh).deformed.has_value());
  auto pose = vtkSmartPointer<vtkStringArray>::New();
  pose->SetName("Pose");
  pose->InsertNextValue("bent");
  data->GetFieldData()->AddArray(pose);
  EXPECT_EQ(test::errorText([&] { isDeformed(data, "odd.vtp"); }),
            "odd.vtp: field data 'Pose' is 'bent', not rest or deformed");
}

}  // namespace
}  // namespace tetskin
