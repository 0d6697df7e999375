// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkPolyData.h>

#include "TestFiles.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin {
namespace {

const std::string kData = std::string(TETSKIN_SOURCE_DIR) + "/data/";

TEST(BindingFile, WriteThenReadIsExact) {
  test::ScratchDir dir;
  const Dataset d = loadDataset(kData + "bunny.json");
  for (BindingMethod method : {BindingMethod::Closest, BindingMethod::Embed}) {
    BoundSurface bound;
    bound.surface = readObj(kData + "bunny.obj");
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

TEST(BindingFile, PlainSurfaceIsNotABinding) {
  test::ScratchDir dir;
  writeSurface(dir / "s.vtp", readObj(kData + "bunny.obj"));
  try {
    readBinding(dir / "s.vtp");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("is not a TetSkin binding"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tetskin
