// SPDX-License-Identifier: AGPL-3.0-or-later
// Render paths against committed baseline images, against each other, and
// the deformed bounds a GPU-deforming mapper reports.
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropPicker.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "ImageCompare.h"
#include "SampleData.h"
#include "Shapes.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/NormalTransforms.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/rendering/FurLayer.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/rendering/XDisplay.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"
#include "vtkTetSkinBufferMapper.h"
#include "vtkTetSkinGpu2PassMapper.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;

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

// A deformation far from affine within each coarse tetrahedron: the
// nodes moved sideways in waves along the height (two per `box` height, of
// a tenth of it).
Points3 waved(const Points3& nodes, const BoundingBox& box) {
  const double height = box.extent().y();
  Points3 out = nodes;
  for (Index v = 0; v < nodes.rows(); ++v) {
    const double phase = 2 * M_PI * (nodes(v, 1) - box.min.y()) / (0.5 * height);
    out(v, 0) += 0.1 * height * std::sin(phase);
    out(v, 2) += 0.1 * height * std::cos(phase);
  }
  return out;
}

class Rendering : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string problem = xDisplayProblem(); !problem.empty())
      GTEST_SKIP() << "needs an X display (run under xvfb-run): " << problem;
    surface_ = readObj(kSampleData + "bunny_8k.obj");
    binding_ = bindSurface(surface_, dataset_.mesh, 1);
  }

  vtkSmartPointer<vtkImageData> render(RenderPath path, const Points3& control) {
    return render(path, control, surface_, binding_, {});
  }

  // The surface bound to level 1, seen from the iso preset at 256x256.
  // With `before`, the frame before `control` (dynamic fur sees the motion).
  vtkSmartPointer<vtkImageData> render(RenderPath path, const Points3& control,
                                       const SurfaceMesh& surface, const SurfaceBinding& binding,
                                       const std::string& texture, const FurParameters& fur = {},
                                       const Points3* before = nullptr) {
    DeformableSurface deformable(dataset_.mesh, surface, binding, path, dataset_.config.material,
                                 texture, fur);
    if (texelLimit_ > 0)
      vtkTetSkinBufferMapper::SafeDownCast(deformable.actor()->GetMapper())
          ->SetTexelLimit(texelLimit_);
    OffscreenView view(256, 256);
    deformable.addTo(view.renderer());
    if (before) {
      deformable.update(*before);
      view.render();  // the GPU keeps the previous frame's positions when it draws one
    }
    deformable.update(control);
    const BoundingBox box = boundingBox(extractLevel(dataset_.mesh, 1).nodes);
    const std::array<double, 6> bounds = toVtkBounds(box);
    view.setCamera(CameraPreset::Iso, bounds.data());
    view.render();
    gpuProblem_ = deformable.gpuProblem();
    return view.capture();
  }

  // The view of render() with nothing in it.
  static vtkSmartPointer<vtkImageData> background() {
    OffscreenView view(256, 256);
    view.render();
    return view.capture();
  }

  static double difference(vtkImageData* a, vtkImageData* b) {
    return test::differingPixelShare(a, b);
  }
  static void write(vtkImageData* image, const std::filesystem::path& path) {
    writePng(path, image);
  }
  static void expectMatchesBaseline(vtkImageData* image, const std::string& name) {
    test::expectMatchesBaseline(image, TETSKIN_BASELINE_DIR, TETSKIN_ACTUAL_DIR, name);
  }

  const Dataset& dataset_ = sampleDataset();
  SurfaceMesh surface_;
  SurfaceBinding binding_;
  vtkIdType texelLimit_ = 0;  // render(): the gpu mappers' SetTexelLimit
  std::string gpuProblem_;    // render(): the DeformableSurface's gpuProblem()
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

// For every kind of binding: triangles with the normal or the displacement
// offset, and embedding tetrahedra.
TEST_F(Rendering, Gpu2PassBufferHoldsTheCpuDeformerPositions) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  for (const auto& [method, offset] : {std::pair{BindingMethod::Closest, OffsetMode::Normal},
                                       std::pair{BindingMethod::Closest, OffsetMode::Displacement},
                                       std::pair{BindingMethod::Embed, OffsetMode::Normal},
                                       std::pair{BindingMethod::Embed, OffsetMode::Displacement}}) {
    const SurfaceBinding binding = bindSurface(surface_, dataset_.mesh, 1, {method, offset});
    const std::string kind = std::string(toString(method)) + ", " + toString(offset);
    DeformableSurface deformable(dataset_.mesh, surface_, binding, RenderPath::Gpu2Pass,
                                 dataset_.config.material);
    deformable.update(control);
    OffscreenView view(64, 64);
    view.renderer()->AddActor(deformable.actor());
    view.render();
    auto* mapper = vtkTetSkinGpu2PassMapper::SafeDownCast(deformable.actor()->GetMapper());
    ASSERT_NE(mapper, nullptr);
    const std::vector<float> gpu = mapper->ReadDeformedPositions(view.window());
    SurfaceDeformer deformer(surface_, binding, dataset_.mesh.nodes);
    Points3 positions, normals;
    deformer.deform(control, positions, normals);
    ASSERT_EQ(gpu.size(), static_cast<std::size_t>(4 * positions.rows()));
    const double diagonal = boundingBox(positions).diagonal();
    double worst = 0;
    for (Index v = 0; v < positions.rows(); ++v)
      for (int k = 0; k < 3; ++k)
        worst =
            std::max(worst, std::abs(gpu[static_cast<std::size_t>(4 * v + k)] - positions(v, k)));
    std::printf("gpu-2pass vs CPU deformer (%s): max |difference| %.2e (%.2e of the diagonal)\n",
                kind.c_str(), worst, worst / diagonal);
    EXPECT_LT(worst / diagonal, 1e-5) << kind;  // single precision on the GPU
  }
}

// gpu-1pass draws the displacement offset where the CPU does: a surface
// moved off the control mesh (by a fifth of its width) is bound with it and
// drawn twisted, unlit, by both paths: the same silhouette. (Lit, they
// differ: gpu-1pass interpolates the normals of control triangles, which
// for a surface this far off face any way.)
TEST_F(Rendering, Gpu1PassDrawsADisplacementBindingAsTheCpuPath) {
  SurfaceMesh moved = surface_;
  const BoundingBox box = boundingBox(extractLevel(dataset_.mesh, 1).nodes);
  moved.positions.col(0).array() += 0.2 * box.extent().x();
  const SurfaceBinding displaced =
      bindSurface(moved, dataset_.mesh, 1, {BindingMethod::Closest, OffsetMode::Displacement});
  auto silhouette = [&](RenderPath path, const Points3& control) {
    DeformableSurface deformable(dataset_.mesh, moved, displaced, path, dataset_.config.material);
    deformable.actor()->GetProperty()->LightingOff();
    OffscreenView view(256, 256);
    deformable.addTo(view.renderer());
    deformable.update(control);
    const std::array<double, 6> bounds = toVtkBounds(box);
    view.setCamera(CameraPreset::Iso, bounds.data());
    view.render();
    return view.capture();
  };
  const Points3 control = twisted(dataset_.mesh.nodes);
  const auto gpu = silhouette(RenderPath::Gpu1Pass, control);
  const double error = difference(silhouette(RenderPath::Cpu, control), gpu);
  const double fromRest = difference(silhouette(RenderPath::Gpu1Pass, dataset_.mesh.nodes), gpu);
  std::printf(
      "pixels differing by > 24/255, unlit: displacement cpu vs gpu-1pass %.3f%%, rest vs "
      "twisted %.2f%%\n",
      100 * error, 100 * fromRest);
  EXPECT_LT(error, 0.002);
  EXPECT_GT(fromRest, 0.05);
}

// An embed binding drawn by gpu-2pass looks as the CPU draws it.
TEST_F(Rendering, Gpu2PassDrawsAnEmbedBindingAsTheCpuPath) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  const SurfaceBinding embed =
      bindSurface(surface_, dataset_.mesh, 1, {BindingMethod::Embed, OffsetMode::Displacement});
  const auto cpu = render(RenderPath::Cpu, control, surface_, embed, "");
  const auto gpu = render(RenderPath::Gpu2Pass, control, surface_, embed, "");
  const double error = difference(cpu, gpu);
  const double moved =
      difference(render(RenderPath::Gpu2Pass, dataset_.mesh.nodes, surface_, embed, ""), gpu);
  std::printf(
      "pixels differing by > 24/255: embed cpu vs gpu-2pass %.3f%%, rest vs twisted %.2f%%\n",
      100 * error, 100 * moved);
  EXPECT_LT(error, 0.002);
  EXPECT_GT(moved, 0.05);  // (the comparison does see the twist)
}

// An embed binding drawn by gpu-1pass: the same positions as the CPU's, and
// normals turned by the nodes' normal transforms. Under a rigid motion
// those are the CPU's normals; twisted they are interpolated where the CPU
// recomputes the surface's own, which at this twist no pixel shows. (With
// the rest normal left unturned, the two comparisons differ in 18% and 13%
// of the pixels.)
TEST_F(Rendering, Gpu1PassDrawsAnEmbedBindingAsTheCpuPath) {
  const SurfaceBinding embed =
      bindSurface(surface_, dataset_.mesh, 1, {BindingMethod::Embed, OffsetMode::Displacement});
  const Points3& rest = dataset_.mesh.nodes;
  const BoundingBox box = boundingBox(extractLevel(dataset_.mesh, 1).nodes);
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 1, -0.2).normalized()).toRotationMatrix();
  Points3 turned = rest;
  for (Index v = 0; v < rest.rows(); ++v)
    turned.row(v) = (centre + turn * (rest.row(v).transpose() - centre)).transpose();
  auto paths = [&](const Points3& control) {
    return difference(render(RenderPath::Cpu, control, surface_, embed, ""),
                      render(RenderPath::Gpu1Pass, control, surface_, embed, ""));
  };
  const double rigid = paths(turned), twist = paths(twisted(rest));
  const double moved = difference(render(RenderPath::Gpu1Pass, rest, surface_, embed, ""),
                                  render(RenderPath::Gpu1Pass, turned, surface_, embed, ""));
  std::printf(
      "pixels differing by > 24/255: embed cpu vs gpu-1pass turned %.3f%%, twisted %.3f%%; rest "
      "vs turned %.2f%%\n",
      100 * rigid, 100 * twist, 100 * moved);
  EXPECT_LT(rigid, 0.002);
  EXPECT_LT(twist, 0.002);
  EXPECT_GT(moved, 0.05);
}

// Under a wave, far from affine within each coarse tetrahedron, gpu-1pass
// shades an embed binding nearly as the CPU, which recomputes the deformed
// surface's own normals (the normals themselves: the next test).
TEST_F(Rendering, Gpu1PassShadesAnEmbedBindingSmoothlyUnderAWave) {
  const SurfaceBinding embed =
      bindSurface(surface_, dataset_.mesh, 1, {BindingMethod::Embed, OffsetMode::Displacement});
  const Points3& rest = dataset_.mesh.nodes;
  const Points3 wave = waved(rest, boundingBox(extractLevel(dataset_.mesh, 1).nodes));
  const auto cpu = render(RenderPath::Cpu, wave, surface_, embed, "");
  const auto gpu = render(RenderPath::Gpu1Pass, wave, surface_, embed, "");
  write(cpu, std::filesystem::path(TETSKIN_ACTUAL_DIR) / "embed_wave_cpu.png");
  write(gpu, std::filesystem::path(TETSKIN_ACTUAL_DIR) / "embed_wave_gpu1pass.png");
  const auto still = render(RenderPath::Cpu, rest, surface_, embed, "");
  const double paths = difference(cpu, gpu), moved = difference(still, cpu);
  const double pathsMean = test::meanPixelDifference(cpu, gpu);
  const double movedMean = test::meanPixelDifference(still, cpu);
  std::printf(
      "embed cpu vs gpu-1pass waved: %.3f%% of the pixels differ by > 24/255, mean difference "
      "%.3f/255; rest vs waved %.2f%%, %.3f/255\n",
      100 * paths, pathsMean, 100 * moved, movedMean);
  EXPECT_GT(moved, 0.05);
  EXPECT_LT(paths, 0.02);  // (1.2% and 1.57/255 with the normals of each tetrahedron)
  EXPECT_LT(pathsMean, 2.5);
}

// gpu-1pass's normals for an embed binding under that wave, against the
// deformed surface's own (the CPU's): each vertex's rest normal turned by
// its tetrahedron's nodes' normal transforms (NormalTransforms.h) as the
// shader does, and, as gpu-1pass did before, by its tetrahedron's own
// cof(F). Per tetrahedron the normals jump across the tetrahedra's faces
// and some point away from the surface's (up to 180 degrees); the nodes'
// means are continuous and stay within 60 degrees.
TEST(EmbedNormals, NodeTransformsFollowTheSurfaceWithoutTheOutliersOfPerTetrahedronNormals) {
  const Dataset& d = sampleDataset();
  const SurfaceMesh surface = readObj(kSampleData + "bunny_8k.obj");
  const SurfaceBinding embed =
      bindSurface(surface, d.mesh, 1, {BindingMethod::Embed, OffsetMode::Displacement});
  const Points3& rest = d.mesh.nodes;
  const Points3 wave = waved(rest, boundingBox(extractLevel(d.mesh, 1).nodes));
  SurfaceDeformer deformer(surface, embed, rest);
  Points3 positions(surface.vertexCount(), 3), normals(surface.vertexCount(), 3);
  deformer.deform(wave, positions, normals);
  const Points3 restNormals = vertexNormals(surface.positions, surface.triangles);
  const LevelRange& level = d.mesh.levels[1];
  const NodeNormalTransforms transforms(
      d.mesh.elements.middleRows(level.firstElement, level.elementCount), rest);
  NormalTransformRows nodeTransforms(rest.rows(), 9);
  transforms.compute(wave, nodeTransforms);
  std::vector<double> perTetrahedron, nodeMeans;  // degrees from the CPU's normal
  auto degrees = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
  };
  for (Index v = 0; v < surface.vertexCount(); ++v) {
    Eigen::Matrix3d D, deformed, G = Eigen::Matrix3d::Zero();
    for (int k = 0; k < 3; ++k) {
      const int first = embed.controlIds(v, 0), other = embed.controlIds(v, k + 1);
      D.col(k) = (rest.row(other) - rest.row(first)).transpose();
      deformed.col(k) = (wave.row(other) - wave.row(first)).transpose();
    }
    for (int k = 0; k < 4; ++k)
      G += embed.weights(v, k) *
           Eigen::Map<const Eigen::Matrix3d>(nodeTransforms.row(embed.controlIds(v, k)).data());
    const Eigen::Vector3d n = restNormals.row(v).transpose(), cpu = normals.row(v).transpose();
    perTetrahedron.push_back(degrees(deformed.inverse().transpose() * D.transpose() * n, cpu));
    nodeMeans.push_back(degrees(G * n, cpu));
  }
  auto percentile = [](std::vector<double> angles, double share) {
    std::sort(angles.begin(), angles.end());
    return angles[static_cast<std::size_t>(share * static_cast<double>(angles.size() - 1))];
  };
  for (const auto& [name, angles] :
       {std::pair{"node means", nodeMeans}, std::pair{"per tetrahedron", perTetrahedron}})
    std::printf("%s: degrees from the surface's own normals: median %.2f, 99%% %.2f, max %.2f\n",
                name, percentile(angles, 0.5), percentile(angles, 0.99), percentile(angles, 1));
  EXPECT_LT(percentile(nodeMeans, 1), 60);
  EXPECT_LT(percentile(nodeMeans, 0.99), percentile(perTetrahedron, 0.99));
  EXPECT_LT(percentile(nodeMeans, 0.5), 5);
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
  const SurfaceMesh textured = readObj(kSampleData + "bunny_8k_tex.obj");
  ASSERT_TRUE(textured.hasTexcoords());
  const SurfaceBinding binding = bindSurface(textured, dataset_.mesh, 1);
  const Points3 control = twisted(dataset_.mesh.nodes);
  const std::string texturePng = kSampleData + "bunny_texture.png";
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
  // A missing texture is named as such first; a good one on a surface
  // without texture coordinates (bunny_8k.obj) cannot be applied.
  auto error = [&](const SurfaceMesh& surface, const SurfaceBinding& bound,
                   const std::string& png) -> std::string {
    try {
      DeformableSurface(dataset_.mesh, surface, bound, RenderPath::Cpu, dataset_.config.material,
                        png);
    } catch (const Error& e) {
      return e.message();
    }
    return "no error";
  };
  EXPECT_EQ(error(surface_, binding_, texturePng),
            "cannot be applied: the surface has no texture coordinates (OBJ 'vt')");
  EXPECT_EQ(error(textured, binding, kSampleData + "no_such.png"), "cannot open for reading");
  EXPECT_EQ(error(textured, binding, kSampleData + "bunny.obj"), "is not a PNG image");
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

// Fur: small, dense and tall enough to see at 256x256; fixed shell count.
FurParameters testFur() {
  FurParameters f;
  f.enabled = true;
  f.shells = 8;
  f.adaptiveShells = false;
  f.length = 0.04;
  f.textureSize = 64;
  f.textureRepeats = 8;
  return f;
}

// A model far from the origin (a site's coordinates): each GPU path draws
// it as it draws the model at the origin. The control positions once went
// to the GPU in single precision as they were, and the surface came out
// jagged (about 2% of the pixels off); they are now measured from the
// level's centre, and the offset goes into VTK's matrices in double.
TEST_F(Rendering, GpuPathsDrawAModelFarFromTheOriginAsAtTheOrigin) {
  auto renderAt = [&](RenderPath path, const Eigen::RowVector3d& offset) {
    MultiLevelTetMesh mesh = dataset_.mesh;
    mesh.nodes.rowwise() += offset;
    SurfaceMesh surface = surface_;
    surface.positions.rowwise() += offset;
    FurParameters fur;
    if (hasFur(path)) fur = testFur();
    DeformableSurface deformable(mesh, surface, binding_, path, dataset_.config.material, "", fur);
    OffscreenView view(256, 256);
    deformable.addTo(view.renderer());
    const Points3 control = twisted(dataset_.mesh.nodes).rowwise() + offset;
    deformable.update(control);
    const BoundingBox box = boundingBox(extractLevel(mesh, 1).nodes);
    const std::array<double, 6> bounds = toVtkBounds(box);
    view.setCamera(CameraPreset::Iso, bounds.data());
    view.render();
    return view.capture();
  };
  const Eigen::RowVector3d far(1e6, -2e6, 5e5);
  // The fur's box texture coordinates are measured from the surface's
  // lowest corner, so its pattern is the same wherever the model is (before,
  // from the origin: fur-gpu 1e6 away was 2.4% off its drawing at the origin).
  for (RenderPath path :
       {RenderPath::Gpu1Pass, RenderPath::Gpu2Pass, RenderPath::FurCpu, RenderPath::FurGpu}) {
    const double error =
        difference(renderAt(path, Eigen::RowVector3d::Zero()), renderAt(path, far));
    std::printf("pixels differing by > 24/255, %s at the origin vs 1e6 away: %.3f%%\n",
                toString(path), 100 * error);
    EXPECT_LT(error, 0.002) << toString(path);
  }
}

// A model turned to z-up (or x-up), seen through the presets of its up
// axis, is drawn as the y-up model through y's: the presets turn with the
// axis (before, a z-up model lay on its back in every view).
TEST_F(Rendering, CameraPresetsFollowTheUpAxis) {
  // The model turned so that its up is `modelUp`, seen through the presets
  // for `cameraUp`.
  auto render = [&](UpAxis modelUp, UpAxis cameraUp, CameraPreset preset) {
    const Eigen::Matrix3d turn = fromYUp(modelUp);
    MultiLevelTetMesh mesh = dataset_.mesh;
    mesh.nodes = (mesh.nodes * turn.transpose()).eval();
    SurfaceMesh surface = surface_;
    surface.positions = (surface.positions * turn.transpose()).eval();
    if (surface.hasNormals()) surface.normals = (surface.normals * turn.transpose()).eval();
    DeformableSurface deformable(mesh, surface, binding_, RenderPath::Cpu,
                                 dataset_.config.material);
    OffscreenView view(256, 256);
    deformable.addTo(view.renderer());
    deformable.update(mesh.nodes);
    const BoundingBox box = boundingBox(extractLevel(mesh, 1).nodes);
    const std::array<double, 6> bounds = toVtkBounds(box);
    view.setCamera(preset, bounds.data(), cameraUp);
    view.render();
    return view.capture();
  };
  for (CameraPreset preset :
       {CameraPreset::Front, CameraPreset::Side, CameraPreset::Top, CameraPreset::Iso}) {
    const auto upright = render(UpAxis::Y, UpAxis::Y, preset);
    for (UpAxis up : {UpAxis::Z, UpAxis::X}) {
      const double error = difference(upright, render(up, up, preset));
      std::printf("preset %d, up %s vs y: %.3f%% of the pixels differ\n", static_cast<int>(preset),
                  toString(up), 100 * error);
      EXPECT_LT(error, 0.002) << "preset " << static_cast<int>(preset) << ", up " << toString(up);
    }
  }
  // (Through y's presets the z-up model is another picture.)
  const double lying = difference(render(UpAxis::Y, UpAxis::Y, CameraPreset::Front),
                                  render(UpAxis::Z, UpAxis::Y, CameraPreset::Front));
  std::printf("the z-up model through y's front preset: %.1f%% differ\n", 100 * lying);
  EXPECT_GT(lying, 0.05);
}

TEST_F(Rendering, FurCpuAndFurGpuMatchTheirBaselinesAndEachOther) {
  // Still: the last two frames the same (no motion; the constructor's first
  // frame is at rest).
  const Points3 control = twisted(dataset_.mesh.nodes);
  const auto cpu = render(RenderPath::FurCpu, control, surface_, binding_, "", testFur(), &control);
  const auto gpu = render(RenderPath::FurGpu, control, surface_, binding_, "", testFur(), &control);
  expectMatchesBaseline(cpu, "fur_cpu_static.png");
  expectMatchesBaseline(gpu, "fur_gpu_static.png");
  const double paths = difference(cpu, gpu);
  const double fur = difference(cpu, render(RenderPath::Cpu, control));
  std::printf("fur-cpu vs fur-gpu %.3f%%, fur vs no fur %.1f%%\n", 100 * paths, 100 * fur);
  EXPECT_LT(paths, 0.01);
  EXPECT_GT(fur, 0.05);  // the fur is there
}

TEST_F(Rendering, DynamicFurTrailsTheMotionOnBothPaths) {
  const Points3 rest = dataset_.mesh.nodes;
  const Points3 control = twisted(rest);
  FurParameters fur = testFur();
  fur.drag = 0.5;
  for (RenderPath path : {RenderPath::FurCpu, RenderPath::FurGpu}) {
    const auto moving = render(path, control, surface_, binding_, "", fur, &rest);
    const auto still = render(path, control, surface_, binding_, "", fur, &control);
    const double change = difference(moving, still);
    std::printf("%s: after motion vs still %.2f%%\n", toString(path), 100 * change);
    EXPECT_GT(change, 0.005) << toString(path);
    expectMatchesBaseline(
        moving, std::string(path == RenderPath::FurCpu ? "fur_cpu" : "fur_gpu") + "_motion.png");
  }
}

TEST_F(Rendering, ColourTextureAlphaMasksTheFur) {
  const SurfaceMesh textured = readObj(kSampleData + "bunny_8k_tex.obj");
  const SurfaceBinding binding = bindSurface(textured, dataset_.mesh, 1);
  const Points3 control = twisted(dataset_.mesh.nodes);
  // The bundled texture with its alpha cleared in the left half (u < 0.5),
  // and cleared everywhere.
  const vtkSmartPointer<vtkImageData> texture = readPng(kSampleData + "bunny_texture.png");
  auto masked = [&](bool half) {
    vtkImageData* in = texture;
    int dims[3];
    in->GetDimensions(dims);
    auto out = vtkSmartPointer<vtkImageData>::New();
    out->SetDimensions(dims);
    out->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    const int channels = in->GetNumberOfScalarComponents();
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        auto* src = static_cast<unsigned char*>(in->GetScalarPointer(x, y, 0));
        auto* dst = static_cast<unsigned char*>(out->GetScalarPointer(x, y, 0));
        for (int c = 0; c < 3; ++c) dst[c] = src[std::min(c, channels - 1)];
        dst[3] = (!half || x < dims[0] / 2) ? 0 : 255;
      }
    const std::filesystem::path file =
        std::filesystem::path(TETSKIN_ACTUAL_DIR) / (half ? "mask_half.png" : "mask_all.png");
    write(out, file);
    return file.string();
  };
  const std::string half = masked(true), all = masked(false);
  FurParameters bald = testFur();
  bald.density = 0;
  const auto halfImage = render(RenderPath::FurCpu, control, textured, binding, half, testFur());
  const auto allImage = render(RenderPath::FurCpu, control, textured, binding, all, testFur());
  const auto noHair = render(RenderPath::FurCpu, control, textured, binding, "", bald);
  const auto furry = render(RenderPath::FurCpu, control, textured, binding, "", testFur());
  // Masked everywhere = no hair at all: only the darkened skin remains.
  EXPECT_LT(difference(allImage, noHair), 0.001);
  // Half masked: differs from both the bald and the fully furred bunny.
  const double fromBald = difference(halfImage, noHair), fromFurry = difference(halfImage, furry);
  std::printf("half mask vs bald %.1f%%, vs unmasked %.1f%%\n", 100 * fromBald, 100 * fromFurry);
  EXPECT_GT(fromBald, 0.01);
  EXPECT_GT(fromFurry, 0.01);
  expectMatchesBaseline(halfImage, "fur_masked.png");
  expectMatchesBaseline(render(RenderPath::FurGpu, control, textured, binding, half, testFur()),
                        "fur_gpu_masked.png");
}

TEST_F(Rendering, FurClosesOverTheSeamsOfBoxTextureCoordinates) {
  // A cube: every edge is a seam between two cube sides. The fur's vertices
  // along a seam share their stitched normals, so the fur wraps round the
  // edges; a "soup" cube (every face its own vertices, flat normals) leaves
  // the fur open there.
  // With hair on every texel, bare skin shows only where the fur opens.
  auto draw = [&](const SurfaceMesh* cube, const std::string& name) {
    OffscreenView view(256, 256);
    auto source = vtkSmartPointer<vtkCubeSource>::New();
    source->SetXLength(2);
    source->SetYLength(2);
    source->SetZLength(2);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(source->GetOutputPort());
    auto skin = vtkSmartPointer<vtkActor>::New();
    skin->SetMapper(mapper);
    skin->GetProperty()->SetColor(0.1, 0.1, 0.6);
    view.renderer()->AddActor(skin);
    FurParameters fur = testFur();
    fur.length = 0.08;
    fur.density = 1;
    fur.textureRepeats = 4;
    std::unique_ptr<FurLayer> layer;
    if (cube) {
      layer = std::make_unique<FurLayer>(*cube, fur, dataset_.config.material, nullptr, nullptr);
      layer->addTo(view.renderer());
      layer->update(cube->positions, vertexNormals(cube->positions, cube->triangles));
    }
    const double bounds[6] = {-1.2, 1.2, -1.2, 1.2, -1.2, 1.2};
    view.setCamera(CameraPreset::Iso, bounds);
    view.render();
    auto image = view.capture();
    if (!name.empty()) expectMatchesBaseline(image, name);
    return image;
  };
  // Pixels of the skin that the fur leaves unchanged.
  const auto bare = draw(nullptr, "");
  auto bareShare = [&](vtkImageData* furred) {
    vtkDataArray* a = bare->GetPointData()->GetScalars();
    vtkDataArray* b = furred->GetPointData()->GetScalars();
    Index skin = 0, unchanged = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
      const bool isSkin = a->GetComponent(i, 2) > a->GetComponent(i, 0) + 60;  // the blue cube
      if (!isSkin) continue;
      ++skin;
      double largest = 0;
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(a->GetComponent(i, c) - b->GetComponent(i, c)));
      unchanged += largest <= 24 ? 1 : 0;
    }
    return static_cast<double>(unchanged) / static_cast<double>(std::max<Index>(skin, 1));
  };
  const SurfaceMesh cube = test::box({-1, -1, -1}, {1, 1, 1});
  const SurfaceMesh soup = test::soup(cube);
  const double stitched = bareShare(draw(&cube, "fur_seam_cube.png"));
  const double split = bareShare(draw(&soup, ""));
  std::printf("bare skin: stitched %.2f%%, split %.2f%%\n", 100 * stitched, 100 * split);
  EXPECT_LT(stitched, 0.002);
  EXPECT_GT(split, stitched + 0.005);
}

// A gpu path whose texture buffers would hold more texels than the OpenGL
// allows (here a limit set below llvmpipe's own) draws nothing and says
// why, instead of drawing from buffers it could not fill; at the limit
// itself it draws as without one.
TEST_F(Rendering, GpuPathsPastTheTexelLimitDrawNothingAndSayWhy) {
  const Points3 control = twisted(dataset_.mesh.nodes);
  const std::string nodes = std::to_string(dataset_.mesh.nodes.rows());
  const std::string vertices = std::to_string(surface_.vertexCount());
  const auto empty = background();
  const auto gpu1 = render(RenderPath::Gpu1Pass, control);
  ASSERT_EQ(gpuProblem_, "");
  const auto gpu2 = render(RenderPath::Gpu2Pass, control);
  ASSERT_EQ(gpuProblem_, "");
  ASSERT_GT(difference(gpu1, empty), 0.05);

  texelLimit_ = dataset_.mesh.nodes.rows();
  EXPECT_EQ(difference(render(RenderPath::Gpu1Pass, control), gpu1), 0.0);
  EXPECT_EQ(gpuProblem_, "");
  texelLimit_ -= 1;
  EXPECT_EQ(difference(render(RenderPath::Gpu1Pass, control), empty), 0.0);
  EXPECT_EQ(gpuProblem_, "gpu-1pass: the positions of " + nodes + " control nodes need " + nodes +
                             " texels in one texture buffer, more than the " +
                             std::to_string(texelLimit_) +
                             " this OpenGL allows (the texel limit set): draw it with the cpu "
                             "path");

  // Embed bindings: three texels a node for the normal transforms.
  const SurfaceBinding embed =
      bindSurface(surface_, dataset_.mesh, 1, {BindingMethod::Embed, OffsetMode::Displacement});
  texelLimit_ = 3 * dataset_.mesh.nodes.rows() - 1;
  EXPECT_EQ(difference(render(RenderPath::Gpu1Pass, control, surface_, embed, ""), empty), 0.0);
  EXPECT_NE(gpuProblem_.find("gpu-1pass: the normal transforms of " + nodes +
                             " control nodes (3 texels each) need " +
                             std::to_string(3 * dataset_.mesh.nodes.rows()) + " texels"),
            std::string::npos)
      << gpuProblem_;

  // gpu-2pass and the fur drawn from its buffers: a texel per surface vertex.
  texelLimit_ = surface_.vertexCount();
  EXPECT_EQ(difference(render(RenderPath::Gpu2Pass, control), gpu2), 0.0);
  EXPECT_EQ(gpuProblem_, "");
  texelLimit_ -= 1;
  for (RenderPath path : {RenderPath::Gpu2Pass, RenderPath::FurGpu}) {
    EXPECT_EQ(difference(render(path, control, surface_, binding_, "", testFur()), empty), 0.0)
        << toString(path);
    EXPECT_NE(gpuProblem_.find("gpu-2pass: the positions of " + vertices +
                               " surface vertices need " + vertices + " texels"),
              std::string::npos)
        << gpuProblem_;
  }
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
