// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/DeformableSurface.h"

#include <vtkActor.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <chrono>
#include <optional>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/NormalTransforms.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/spatial/Aabb.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"
#include "vtkTetSkinGpu2PassMapper.h"
#include "vtkTetSkinGpuDeformMapper.h"

namespace tetskin {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void applyMaterial(vtkActor* actor, const Material& m) {
  vtkProperty* p = actor->GetProperty();
  p->SetInterpolationToPhong();  // per-pixel lighting, as in the report's measurements
  p->SetColor(m.color[0], m.color[1], m.color[2]);
  p->SetSpecular(m.specular);
  p->SetSpecularPower(m.shininess);
  p->SetDiffuse(0.8);
  p->SetAmbient(0.1);
}

// Per surface vertex the GPU paths' shift (x, y, z, d): the vertex is sum
// w_i X_i + (x, y, z) + d n, n the deformed control triangle's unit normal.
// (x, y, z) is the Displacement offset's constant part, d the Normal one's.
std::vector<float> gpuShifts(const SurfaceBinding& binding, const Points3& restSurface,
                             const Points3& controlRest) {
  const Index n = binding.vertexCount();
  const Points3 shifted = binding.offset == OffsetMode::Displacement
                              ? displacementShifts(binding, restSurface, controlRest)
                              : Points3::Zero(n, 3);
  std::vector<float> shifts(static_cast<std::size_t>(4 * n), 0.0f);
  for (Index v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k)
      shifts[static_cast<std::size_t>(4 * v + k)] = static_cast<float>(shifted(v, k));
    if (binding.offset == OffsetMode::Normal)
      shifts[static_cast<std::size_t>(4 * v + 3)] = static_cast<float>(binding.distance[v]);
  }
  return shifts;
}

// Adds `values` (`components` per point, one tuple per point) to the points
// of `poly` as the float array `name`: a vertex attribute of the GPU mappers.
void addPointArray(vtkPolyData* poly, const char* name, int components,
                   const std::vector<float>& values) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(poly->GetNumberOfPoints());
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  poly->GetPointData()->AddArray(array);
}

}  // namespace

struct DeformableSurface::Impl {
  RenderPath path;
  vtkSmartPointer<vtkPolyData> polyData;
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  std::unique_ptr<SurfaceDeformer> deformer;
  vtkSmartPointer<vtkTetSkinGpuDeformMapper> gpuMapper;
  // gpu-1pass with an embed binding: the control nodes' normal transforms
  // instead of control normals.
  std::optional<NodeNormalTransforms> normalTransforms;
  NormalTransformRows normalTransformRows;
  vtkSmartPointer<vtkTetSkinGpu2PassMapper> gpu2Mapper;
  // gpu path: control vertex normals over the bound level's boundary.
  Triangles boundary;
  VertexTriangleAdjacency boundaryAdjacency;
  Points3 boundaryScratch, controlNormals;
  std::vector<float> controlPositionsF, controlNormalsF;
  // gpu paths: the control positions go to the GPU measured from here (the
  // bound level's rest centre), in single precision (the mappers'
  // SetModelOrigin).
  Eigen::RowVector3d origin = Eigen::RowVector3d::Zero();
  double bounds[6] = {0, -1, 0, -1, 0, -1};
  double maxDistance = 0;
  std::unique_ptr<FurLayer> fur;
};

DeformableSurface::DeformableSurface(const MultiLevelTetMesh& dataset,
                                     const SurfaceMesh& restSurface, const SurfaceBinding& binding,
                                     RenderPath path, const Material& material,
                                     const std::filesystem::path& texture, const FurParameters& fur)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.path = path;
  const RenderPath skin = skinPath(path);
  BoundSurface bound{restSurface, binding, "", std::nullopt};
  bound.surface.normals = vertexNormals(restSurface.positions, restSurface.triangles);
  s.polyData = bindingToPolyData(bound);
  s.maxDistance = binding.distance.cwiseAbs().maxCoeff();
  if (skin == RenderPath::Cpu) {
    s.deformer = std::make_unique<SurfaceDeformer>(restSurface, binding, dataset.nodes);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(s.polyData);
    mapper->ScalarVisibilityOff();
    s.actor->SetMapper(mapper);
  } else {
    validateBinding(binding, restSurface.vertexCount(), dataset.nodes.rows(), "binding");
    const int level = binding.level < 0 ? dataset.finestLevel() : binding.level;
    const LevelRange& r = dataset.levels.at(static_cast<std::size_t>(level));
    const TetMesh controlLevel = extractLevel(dataset, level);
    s.boundary = boundaryFaces(controlLevel, static_cast<int>(r.firstNode)).faces;
    s.origin = boundingBox(controlLevel.nodes).center().transpose();
    s.boundaryAdjacency = vertexTriangleAdjacency(s.boundary, dataset.nodes.rows());
    s.boundaryScratch.resize(s.boundary.rows(), 3);
    s.controlNormals.resize(dataset.nodes.rows(), 3);
    const std::vector<float> shifts = gpuShifts(binding, restSurface.positions, dataset.nodes);
    using ShiftRows = Eigen::Matrix<float, Eigen::Dynamic, 4, Eigen::RowMajor>;
    const Eigen::Map<const ShiftRows> shiftRows(shifts.data(), restSurface.vertexCount(), 4);
    s.maxDistance = std::max<double>(s.maxDistance,  // (the bounds' margin)
                                     shiftRows.leftCols<3>().rowwise().norm().maxCoeff());
    if (skin == RenderPath::Gpu1Pass) {
      // The shifts as a vertex attribute (vtkTetSkinGpuDeformMapper).
      addPointArray(s.polyData, vtkTetSkinGpuDeformMapper::kShiftArray, 4, shifts);
      s.gpuMapper = vtkSmartPointer<vtkTetSkinGpuDeformMapper>::New();
      if (binding.method == BindingMethod::Embed) {
        // (An embedding tetrahedron has no control vertex normals to
        // interpolate: the shader turns the rest normals, the polydata's
        // Normals, by the nodes' normal transforms.)
        s.gpuMapper->SetEmbedBinding(true);
        s.normalTransforms.emplace(dataset.elements.middleRows(r.firstElement, r.elementCount),
                                   dataset.nodes);
        s.normalTransformRows.resize(dataset.nodes.rows(), 9);
      }
      s.gpuMapper->SetModelOrigin(s.origin.data());
      s.gpuMapper->SetInputData(s.polyData);
      s.gpuMapper->ScalarVisibilityOff();
      s.actor->SetMapper(s.gpuMapper);
    } else {
      s.gpu2Mapper = vtkSmartPointer<vtkTetSkinGpu2PassMapper>::New();
      // The binding as SurfaceDeformer reads it, 4 values per vertex each.
      const Index n = restSurface.vertexCount();
      const int controls = binding.controlsPerVertex();
      std::vector<int> ids(static_cast<std::size_t>(4 * n), -1);
      std::vector<float> weights(static_cast<std::size_t>(4 * n), 0.0f);
      for (Index v = 0; v < n; ++v)
        for (int k = 0; k < controls; ++k) {
          ids[static_cast<std::size_t>(4 * v + k)] = binding.controlIds(v, k);
          weights[static_cast<std::size_t>(4 * v + k)] = static_cast<float>(binding.weights(v, k));
        }
      const std::vector<int> triangles(restSurface.triangles.data(),
                                       restSurface.triangles.data() + restSurface.triangles.size());
      const VertexTriangleAdjacency ring =
          vertexTriangleAdjacency(restSurface.triangles, restSurface.vertexCount());
      s.gpu2Mapper->SetSurface(ids, weights, shifts, triangles, ring.offsets, ring.triangles);
      s.gpu2Mapper->SetModelOrigin(s.origin.data());
      s.gpu2Mapper->SetInputData(s.polyData);
      s.gpu2Mapper->ScalarVisibilityOff();
      s.actor->SetMapper(s.gpu2Mapper);
    }
  }
  applyMaterial(s.actor, material);
  vtkSmartPointer<vtkImageData> image;
  if (!texture.empty()) {
    image = readPng(texture);  // (a missing or broken texture is named first)
    if (!restSurface.hasTexcoords())
      throw Error(texture.string(), 0,
                  "cannot be applied: the surface has no texture coordinates (OBJ 'vt')");
  }
  if (hasFur(path)) {
    // The skin under the fur: darker, its highlight weaker and broader.
    vtkProperty* p = s.actor->GetProperty();
    p->SetColor(material.color[0] * fur.baseDarkening, material.color[1] * fur.baseDarkening,
                material.color[2] * fur.baseDarkening);
    p->SetSpecular(0.3 * material.specular);
    p->SetSpecularPower(std::max(1.0, material.shininess / 4));
    s.fur = std::make_unique<FurLayer>(restSurface, fur, material, image, s.gpu2Mapper);
  } else if (image) {
    auto vtkTex = vtkSmartPointer<vtkTexture>::New();
    vtkTex->SetInputData(image);
    vtkTex->InterpolateOn();
    vtkTex->RepeatOn();
    s.actor->SetTexture(vtkTex);
    s.actor->GetProperty()->SetColor(1, 1, 1);  // the texture gives the colour
  }
  update(dataset.nodes);
}

DeformableSurface::~DeformableSurface() = default;

RenderPath DeformableSurface::path() const {
  return impl_->path;
}
vtkActor* DeformableSurface::actor() const {
  return impl_->actor;
}
vtkPolyData* DeformableSurface::polyData() const {
  return impl_->polyData;
}
const double* DeformableSurface::bounds() const {
  return impl_->bounds;
}
std::string DeformableSurface::gpuProblem() const {
  if (impl_->gpuMapper) return impl_->gpuMapper->GetGpuProblem();
  if (impl_->gpu2Mapper) return impl_->gpu2Mapper->GetGpuProblem();
  return {};
}
FurLayer* DeformableSurface::fur() const {
  return impl_->fur.get();
}
void DeformableSurface::addTo(vtkRenderer* renderer) {
  renderer->AddActor(impl_->actor);
  if (impl_->fur) impl_->fur->addTo(renderer);
}
void DeformableSurface::setFrameSeconds(double seconds) {
  if (impl_->fur) impl_->fur->setFrameSeconds(seconds);
}

FrameTimes DeformableSurface::update(const Points3& control) {
  Impl& s = *impl_;
  FrameTimes times;
  auto start = std::chrono::steady_clock::now();
  if (s.deformer) {
    // The kernel writes into the drawn arrays (double, made by
    // bindingToPolyData), the fur reading them there.
    vtkPoints* points = s.polyData->GetPoints();
    auto* positions = vtkDoubleArray::SafeDownCast(points->GetData());
    auto* normals = vtkDoubleArray::SafeDownCast(s.polyData->GetPointData()->GetNormals());
    Eigen::Map<Points3> positionRows = vectorRows(positions);
    Eigen::Map<Points3> normalRows = vectorRows(normals);
    s.deformer->deform(control, positionRows, normalRows);
    if (s.fur) s.fur->update(positionRows, normalRows);
    times.deformSeconds = secondsSince(start);
    start = std::chrono::steady_clock::now();
    points->Modified();
    normals->Modified();
    s.polyData->Modified();
    s.polyData->GetBounds(s.bounds);
    times.uploadSeconds = secondsSince(start);
    return times;
  }
  s.controlPositionsF.resize(static_cast<std::size_t>(control.size()));
  for (Index node = 0; node < control.rows(); ++node)
    for (int k = 0; k < 3; ++k)
      s.controlPositionsF[static_cast<std::size_t>(3 * node + k)] =
          static_cast<float>(control(node, k) - s.origin[k]);
  if (s.normalTransforms) s.normalTransforms->compute(control, s.normalTransformRows);
  const bool controlNormalsNeeded = s.gpuMapper && !s.normalTransforms;
  if (controlNormalsNeeded) {
    computeVertexNormals(control, s.boundary, s.boundaryAdjacency, s.boundaryScratch,
                         s.controlNormals);
    s.controlNormalsF.assign(s.controlNormals.data(),
                             s.controlNormals.data() + s.controlNormals.size());
  }
  // Bounds: the boundary nodes' box grown by the largest offset, plus 1% of
  // its size for vertices bound slightly outside their triangle.
  Aabb box;
  for (Index f = 0; f < s.boundary.rows(); ++f)
    for (int k = 0; k < 3; ++k) box.extend(control.row(s.boundary(f, k)).transpose());
  const double margin = s.maxDistance + 0.01 * (box.max - box.min).norm();
  for (int k = 0; k < 3; ++k) {
    s.bounds[2 * k] = box.min[k] - margin;
    s.bounds[2 * k + 1] = box.max[k] + margin;
  }
  times.deformSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  if (s.gpuMapper) {
    if (s.normalTransforms)
      s.gpuMapper->SetEmbedState(s.controlPositionsF.data(), s.normalTransformRows.data(),
                                 control.rows());
    else
      s.gpuMapper->SetControlState(s.controlPositionsF.data(), s.controlNormalsF.data(),
                                   control.rows());
    s.gpuMapper->SetDeformedBounds(s.bounds);
  } else {
    s.gpu2Mapper->SetControlPositions(s.controlPositionsF.data(), control.rows());
    s.gpu2Mapper->SetDeformedBounds(s.bounds);
  }
  times.uploadSeconds = secondsSince(start);
  return times;
}

}  // namespace tetskin
