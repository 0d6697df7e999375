// SPDX-License-Identifier: AGPL-3.0-or-later
// Render paths against committed baseline images, against each other, and
// the deformed bounds a GPU-deforming mapper reports.
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPropPicker.h>
#include <vtkRenderer.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/rendering/vtkTetSkinGpu2PassMapper.h"

namespace tetskin {
namespace {

const std::string kData = std::string(TETSKIN_SOURCE_DIR) + "/data/";

// The known deformation frame: the control nodes twisted about y.
Points3 twisted(const Points3& nodes) {
  Points3 out = nodes;
  for (Index v = 0; v < nodes.rows(); ++v) {
    const double angle = 0.08 * nodes(v, 1);
    const Eigen::AngleAxisd turn(angle, Eigen::Vector3d::UnitY());
    out.row(v) = (turn * Eigen::Vector3d(nodes.row(v).transpose())).transpose();
  }
  return out;
}

class Rendering : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    dataset_ = loadDataset(kData + "bunny.json");
    surface_ = readObj(kData + "bunny_8k.obj");
    binding_ = bindSurface(surface_, dataset_.mesh, 1);
  }

  vtkSmartPointer<vtkImageData> render(RenderPath path, const Points3& control) {
    return render(path, control, surface_, binding_, {});
  }

  // The surface bound to level 1, seen from the iso preset at 256x256.
  vtkSmartPointer<vtkImageData> render(RenderPath path, const Points3& control,
                                       const SurfaceMesh& surface, const SurfaceBinding& binding,
                                       const std::string& texture) {
    DeformableSurface deformable(dataset_.mesh, surface, binding, path, dataset_.config.material,
                                 texture);
    deformable.update(control);
    OffscreenView view(256, 256);
    view.renderer()->AddActor(deformable.actor());
    const BoundingBox box = boundingBox(extractLevel(dataset_.mesh, 1).nodes);
    const double bounds[6] = {box.min.x(), box.max.x(), box.min.y(),
                              box.max.y(), box.min.z(), box.max.z()};
    view.setCamera(CameraPreset::Iso, bounds);
    view.render();
    return view.capture();
  }

  // Share of pixels whose largest channel difference exceeds 24 of 255
  // (vtkImageDifference's default tolerance would pass very different images).
  static double difference(vtkImageData* a, vtkImageData* b) {
    EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    vtkDataArray* pa = a->GetPointData()->GetScalars();
    vtkDataArray* pb = b->GetPointData()->GetScalars();
    const int channels = std::min(3, pa->GetNumberOfComponents());
    Index differing = 0;
    for (vtkIdType i = 0; i < pa->GetNumberOfTuples(); ++i) {
      double largest = 0;
      for (int c = 0; c < channels; ++c)
        largest = std::max(largest, std::abs(pa->GetComponent(i, c) - pb->GetComponent(i, c)));
      differing += largest > 24 ? 1 : 0;
    }
    return static_cast<double>(differing) / static_cast<double>(pa->GetNumberOfTuples());
  }

  static void write(vtkImageData* image, const std::filesystem::path& path) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    writer->Write();
  }

  // Compares with the committed baseline; TETSKIN_UPDATE_BASELINES=1 rewrites it.
  static void expectMatchesBaseline(vtkImageData* image, const std::string& name) {
    const std::filesystem::path baseline = std::filesystem::path(TETSKIN_BASELINE_DIR) / name;
    const std::filesystem::path actual = std::filesystem::path(TETSKIN_ACTUAL_DIR) / name;
    write(image, actual);
    if (std::getenv("TETSKIN_UPDATE_BASELINES")) write(image, baseline);
    ASSERT_TRUE(std::filesystem::exists(baseline))
        << "no baseline " << baseline << "; the rendered image is " << actual
        << " (TETSKIN_UPDATE_BASELINES=1 makes it the baseline)";
    auto reader = vtkSmartPointer<vtkPNGReader>::New();
    reader->SetFileName(baseline.c_str());
    reader->Update();
    const double error = difference(image, reader->GetOutput());
    EXPECT_LT(error, 0.002) << name << " differs from its baseline in " << 100 * error
                            << "% of the pixels; see " << actual;
  }

  Dataset dataset_;
  SurfaceMesh surface_;
  SurfaceBinding binding_;
};

TEST_F(Rendering, CpuPathMatchesItsBaseline) {
  expectMatchesBaseline(render(RenderPath::Cpu, twisted(dataset_.mesh.nodes)), "cpu_twist.png");
}

TEST_F(Rendering, Gpu1PassMatchesItsBaseline) {
  expectMatchesBaseline(render(RenderPath::Gpu1Pass, twisted(dataset_.mesh.nodes)),
                        "gpu1pass_twist.png");
}

TEST_F(Rendering, Gpu2PassMatchesItsBaseline) {
  expectMatchesBaseline(render(RenderPath::Gpu2Pass, twisted(dataset_.mesh.nodes)),
                        "gpu2pass_twist.png");
}

TEST_F(Rendering, Gpu2PassEqualsTheCpuPath) {
  // Same positions and the same smooth normals, computed on the GPU.
  const Points3 control = twisted(dataset_.mesh.nodes);
  const double error =
      difference(render(RenderPath::Cpu, control), render(RenderPath::Gpu2Pass, control));
  std::printf("pixels differing by > 24/255: cpu vs gpu-2pass %.3f%%\n", 100 * error);
  EXPECT_LT(error, 0.002);
}

TEST_F(Rendering, Gpu2PassBufferHoldsTheCpuDeformerPositions) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  DeformableSurface deformable(dataset_.mesh, surface_, binding_, RenderPath::Gpu2Pass,
                               dataset_.config.material);
  deformable.update(control);
  OffscreenView view(64, 64);
  view.renderer()->AddActor(deformable.actor());
  view.render();
  auto* mapper = vtkTetSkinGpu2PassMapper::SafeDownCast(deformable.actor()->GetMapper());
  ASSERT_NE(mapper, nullptr);
  const std::vector<float> gpu = mapper->ReadDeformedPositions(view.window());
  SurfaceDeformer deformer(surface_, binding_, dataset_.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(control, positions, normals);
  ASSERT_EQ(gpu.size(), static_cast<std::size_t>(4 * positions.rows()));
  const double diagonal = boundingBox(positions).diagonal();
  double worst = 0;
  for (Index v = 0; v < positions.rows(); ++v)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(gpu[static_cast<std::size_t>(4 * v + k)] - positions(v, k)));
  std::printf("gpu-2pass vs CPU deformer: max |difference| %.2e (%.2e of the diagonal)\n", worst,
              worst / diagonal);
  EXPECT_LT(worst / diagonal, 1e-5);  // single precision on the GPU
}

TEST_F(Rendering, HardwarePickingSeesTheDeformedSurface) {
  // Move the control mesh far to the side: only the GPU-deformed surface is
  // there, the rest-pose points (what the CPU knows) are not.
  Points3 moved = dataset_.mesh.nodes;
  moved.col(0).array() += 30.0;
  for (RenderPath path : {RenderPath::Gpu1Pass, RenderPath::Gpu2Pass}) {
    DeformableSurface deformable(dataset_.mesh, surface_, binding_, path, dataset_.config.material);
    deformable.update(moved);
    OffscreenView view(200, 200);
    view.renderer()->AddActor(deformable.actor());
    view.setCamera(CameraPreset::Front, deformable.bounds());
    view.render();
    auto picker = vtkSmartPointer<vtkPropPicker>::New();
    EXPECT_TRUE(picker->Pick(100, 100, 0, view.renderer())) << toString(path);
    EXPECT_EQ(picker->GetActor(), deformable.actor()) << toString(path);
    EXPECT_FALSE(picker->Pick(2, 2, 0, view.renderer())) << toString(path);  // background
  }
}

TEST_F(Rendering, TextureIsDrawnAlikeByCpuAndGpu2Pass) {
  const SurfaceMesh textured = readObj(kData + "bunny_8k_tex.obj");
  ASSERT_TRUE(textured.hasTexcoords());
  const SurfaceBinding binding = bindSurface(textured, dataset_.mesh, 1);
  const Points3 control = twisted(dataset_.mesh.nodes);
  const std::string texturePng = kData + "bunny_texture.png";
  auto draw = [&](RenderPath path, bool withTexture) {
    return render(path, control, textured, binding, withTexture ? texturePng : std::string());
  };
  const auto cpu = draw(RenderPath::Cpu, true);
  const double paths = difference(cpu, draw(RenderPath::Gpu2Pass, true));
  const double texture = difference(cpu, draw(RenderPath::Cpu, false));
  std::printf("textured: cpu vs gpu-2pass %.3f%%, with vs without texture %.2f%%\n", 100 * paths,
              100 * texture);
  EXPECT_LT(paths, 0.002);
  EXPECT_GT(texture, 0.05);  // the spots are there
  EXPECT_THROW(DeformableSurface(dataset_.mesh, surface_, binding_, RenderPath::Cpu,
                                 dataset_.config.material, kData + "bunny_texture.png"),
               Error);  // bunny_8k.obj has no texture coordinates
}

TEST_F(Rendering, PathsAgree) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  const auto cpu = render(RenderPath::Cpu, control);
  const auto gpu = render(RenderPath::Gpu1Pass, control);
  // Same geometry; gpu-1pass interpolates control-vertex normals (as the
  // report did), so shading differs a little.
  const double error = difference(cpu, gpu);
  const auto rest = render(RenderPath::Gpu1Pass, dataset_.mesh.nodes);
  const double moved = difference(rest, gpu);
  std::printf("pixels differing by > 24/255: cpu vs gpu-1pass %.2f%%, rest vs twisted %.2f%%\n",
              100 * error, 100 * moved);
  EXPECT_LT(error, 0.03);
  EXPECT_GT(moved, 3 * error);  // the comparison does see a real change of shape
}

TEST_F(Rendering, GpuMapperBoundsContainTheDeformedSurface) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  DeformableSurface deformable(dataset_.mesh, surface_, binding_, RenderPath::Gpu1Pass,
                               dataset_.config.material);
  deformable.update(control);
  double bounds[6];
  deformable.actor()->GetMapper()->GetBounds(bounds);
  SurfaceDeformer deformer(surface_, binding_, dataset_.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(control, positions, normals);
  const BoundingBox box = boundingBox(positions);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(bounds[2 * k], box.min[k]);
    EXPECT_GE(bounds[2 * k + 1], box.max[k]);
    // ...and not absurdly larger.
    EXPECT_LT(bounds[2 * k + 1] - bounds[2 * k], 1.2 * (box.max[k] - box.min[k]));
  }
}

}  // namespace
}  // namespace tetskin
