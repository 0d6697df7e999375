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
#include <vtkRenderer.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/rendering/OffscreenView.h"

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
    DeformableSurface deformable(dataset_.mesh, surface_, binding_, path, dataset_.config.material);
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
