// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <functional>
#include <string>

#include "SampleData.h"
#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"
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
    bound.dataset = "../data/bunny.json";
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
// (checked against the dataset), any other surface file without one,
// whatever point arrays it carries.
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
  // The binding arrays without the field data: a plain surface.
  vtkSmartPointer<vtkPolyData> arraysOnly = bindingToPolyData(bound);
  arraysOnly->GetFieldData()->Initialize();
  writeVtp(dir / "arrays.vtp", arraysOnly);
  writeSurface(dir / "plain.vtp", bound.surface);
  for (const char* name : {"arrays.vtp", "plain.vtp"}) {
    const SurfaceOrBinding plain = readSurfaceOrBinding(dir / name, d.mesh);
    EXPECT_FALSE(plain.binding.has_value()) << name;
    EXPECT_EQ(plain.surface.triangles, bound.surface.triangles) << name;
  }
  EXPECT_FALSE(readSurfaceOrBinding(kSampleData + "bunny.obj", d.mesh).binding.has_value());
  // A binding that does not fit the dataset is an error, as readBinding's.
  bound.binding.level = 7;
  writeBinding(dir / "bad.vtp", bound);
  EXPECT_THROW(readSurfaceOrBinding(dir / "bad.vtp", d.mesh), Error);
}

}  // namespace
}  // namespace tetskin
