// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/FurLayer.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/fur/FurGeometry.h"
#include "tetskin/fur/FurTexture.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "vtkTetSkinGpu2PassMapper.h"
#include "vtkTetSkinGpuFurMapper.h"

namespace tetskin {
namespace {

// The static attributes of fur vertices as VTK point arrays; points and
// normals are filled per frame (fur-cpu) or are placeholders (fur-gpu).
vtkSmartPointer<vtkPolyData> furPolyData(const FurMesh& mesh, const SurfaceMesh& rest) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  const Index n = mesh.vertexCount();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (Index i = 0; i < n; ++i)
    points->SetPoint(i, rest.positions.row(mesh.source[static_cast<std::size_t>(i)]).data());
  poly->SetPoints(points);
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetName(arrays::kNormals);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  normals->Fill(0);
  poly->GetPointData()->SetNormals(normals);
  auto array = [&](const char* name, int components) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(n);
    poly->GetPointData()->AddArray(a);
    return a;
  };
  auto tcoords = array("FurTCoords", 2), height = array("FurHeight", 1),
       color = array("ColorTCoords", 2), source = array("FurSource", 1);
  for (Index i = 0; i < n; ++i) {
    const auto v = static_cast<std::size_t>(i);
    tcoords->SetTuple2(i, mesh.texcoords(i, 0), mesh.texcoords(i, 1));
    height->SetValue(i, mesh.height[v]);
    source->SetValue(i, static_cast<float>(mesh.source[v]));
    if (rest.hasTexcoords())
      color->SetTuple2(i, rest.texcoords(mesh.source[v], 0), rest.texcoords(mesh.source[v], 1));
    else
      color->SetTuple2(i, 0, 0);
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    const vtkIdType ids[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
  return poly;
}

}  // namespace

struct FurLayer::Impl {
  FurParameters params;
  SurfaceMesh rest;
  BoxTexturedSurface box;
  FurMesh shells, fins;
  double length = 0, tileSize = 1, frameSeconds = 1.0 / 60.0;
  FurDynamicsOptions dynamics;
  bool gpu = false;
  int shellCount = 0;  // fur-cpu: shells of the current geometry
  vtkSmartPointer<vtkPolyData> shellPoly, finPoly;
  vtkSmartPointer<vtkActor> shellActor, finActor;
  vtkSmartPointer<vtkTetSkinFurMapper> shellMapper, finMapper;
  vtkWeakPointer<vtkRenderer> renderer;
  Points3 previous, velocities;
  bool havePrevious = false;
  double bounds[6] = {0, -1, 0, -1, 0, -1};

  void configure(vtkTetSkinFurMapper* mapper, const Material& material, vtkImageData* color,
                 const FurTexture& texture, bool isFins) {
    mapper->SetFurTexture(texture.size, texture.layers, texture.rgba);
    mapper->SetColorTexture(color);
    mapper->SetFins(isFins);
    mapper->SetKajiyaKay(params.lighting == FurLighting::KajiyaKay);
    mapper->SetVelvet(params.velvet);
    mapper->SetTint(color ? std::array<double, 3>{1, 1, 1} : material.color);
  }

  vtkSmartPointer<vtkActor> makeActor(vtkTetSkinFurMapper* mapper, const Material& material) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->ForceTranslucentOn();  // after the skin, blended, no depth writes
    actor->PickableOff();         // picking means the skin
    vtkProperty* p = actor->GetProperty();
    p->SetInterpolationToPhong();
    p->SetSpecular(std::max(material.specular, 0.2));
    p->SetSpecularPower(material.shininess);
    p->BackfaceCullingOff();
    return actor;
  }

  // fur-cpu: (re)build the shell geometry for `count` shells.
  void buildShells(int count) {
    shells = shellMesh(box, shellHeights(count));
    shellPoly = furPolyData(shells, rest);
    shellMapper->SetInputData(shellPoly);
    shellCount = count;
  }

  int wantedShells() const {
    if (!params.adaptiveShells || !renderer) return params.shells;
    return adaptiveShellCount(vtkTetSkinFurMapper::FurPixelHeight(renderer, bounds, length),
                              params.minShells, params.shells);
  }
};

FurLayer::FurLayer(const SurfaceMesh& rest, const FurParameters& fur, const Material& material,
                   vtkImageData* colorTexture, vtkTetSkinGpu2PassMapper* gpuSkin)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  if (rest.vertexCount() == 0 || rest.triangleCount() == 0)
    throw Error("fur needs a surface with triangles");
  if (colorTexture && !rest.hasTexcoords())
    throw Error("the fur colour texture needs a surface with texture coordinates");
  s.params = fur;
  s.rest = rest;
  s.gpu = gpuSkin != nullptr;
  const BoundingBox box = boundingBox(rest);
  const double diagonal = (box.max - box.min).norm();
  s.length = fur.length * diagonal;
  s.tileSize = diagonal / fur.textureRepeats;
  s.dynamics.drag = fur.drag;
  s.dynamics.maxBend = fur.maxBend;
  s.box = boxTexcoords(rest.positions, rest.triangles, s.tileSize);
  FurTextureOptions t;
  t.size = fur.textureSize;
  t.density = fur.density;
  t.seed = fur.seed;
  t.rootShade = fur.rootShade;
  const FurTexture texture = generateFurTexture(t);
  for (int k = 0; k < 3; ++k) {
    s.bounds[2 * k] = box.min[k];
    s.bounds[2 * k + 1] = box.max[k];
  }
  if (s.gpu) {
    auto shellMapper = vtkSmartPointer<vtkTetSkinGpuFurMapper>::New();
    shellMapper->SetSource(gpuSkin);
    shellMapper->SetModelOrigin(gpuSkin->GetModelOrigin());  // (the skin's positions it reads)
    shellMapper->SetShells(fur.shells, fur.minShells, fur.adaptiveShells);
    s.shells = shellMesh(s.box, {0.0f});  // instances add the shell height
    s.shellPoly = furPolyData(s.shells, rest);
    shellMapper->SetInputData(s.shellPoly);
    s.shellMapper = shellMapper;
  } else {
    s.shellMapper = vtkSmartPointer<vtkTetSkinFurMapper>::New();
    s.buildShells(fur.shells);
  }
  s.configure(s.shellMapper, material, colorTexture, texture, false);
  s.shellActor = s.makeActor(s.shellMapper, material);
  if (fur.fins) {
    s.fins = finMesh(rest.positions, rest.triangles, s.tileSize, fur.seed);
    s.finPoly = furPolyData(s.fins, rest);
    if (s.gpu) {
      auto finMapper = vtkSmartPointer<vtkTetSkinGpuFurMapper>::New();
      finMapper->SetSource(gpuSkin);
      finMapper->SetModelOrigin(gpuSkin->GetModelOrigin());
      finMapper->SetShells(0, 0, false);
      s.finMapper = finMapper;
    } else {
      s.finMapper = vtkSmartPointer<vtkTetSkinFurMapper>::New();
    }
    s.finMapper->SetInputData(s.finPoly);
    s.configure(s.finMapper, material, colorTexture, texture, true);
    s.finActor = s.makeActor(s.finMapper, material);
  }
  setFrameSeconds(s.frameSeconds);
}

FurLayer::~FurLayer() = default;

void FurLayer::addTo(vtkRenderer* renderer) {
  impl_->renderer = renderer;
  renderer->AddActor(impl_->shellActor);
  if (impl_->finActor) renderer->AddActor(impl_->finActor);
}

std::vector<vtkActor*> FurLayer::actors() const {
  std::vector<vtkActor*> out{impl_->shellActor};
  if (impl_->finActor) out.push_back(impl_->finActor);
  return out;
}

double FurLayer::length() const {
  return impl_->length;
}

int FurLayer::shellsDrawn() const {
  if (auto* gpu = vtkTetSkinGpuFurMapper::SafeDownCast(impl_->shellMapper))
    return gpu->GetShellsDrawn();
  return impl_->shellCount;
}

void FurLayer::setFrameSeconds(double seconds) {
  Impl& s = *impl_;
  s.frameSeconds = seconds;
  for (vtkTetSkinFurMapper* m : {s.shellMapper.GetPointer(), s.finMapper.GetPointer()})
    if (auto* gpu = vtkTetSkinGpuFurMapper::SafeDownCast(m))
      gpu->SetDynamics(s.length, seconds, s.dynamics.drag, s.dynamics.maxBend, s.dynamics.minLift);
}

void FurLayer::update(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals) {
  Impl& s = *impl_;
  if (s.gpu) return;
  if (s.havePrevious)
    furVelocities(s.previous, positions, s.frameSeconds, s.velocities);
  else
    s.velocities.setZero(positions.rows(), 3);
  s.previous = positions;
  s.havePrevious = true;
  const Eigen::Vector3d lo = positions.colwise().minCoeff(), hi = positions.colwise().maxCoeff();
  for (int k = 0; k < 3; ++k) {
    s.bounds[2 * k] = lo[k];
    s.bounds[2 * k + 1] = hi[k];
  }
  const int wanted = s.wantedShells();
  if (wanted != s.shellCount) s.buildShells(wanted);
  // Straight into the drawn arrays (double, made by furPolyData).
  auto place = [&](const FurMesh& mesh, vtkPolyData* poly) {
    vtkPoints* points = poly->GetPoints();
    auto* pointArray = vtkDoubleArray::SafeDownCast(points->GetData());
    auto* normalArray = vtkDoubleArray::SafeDownCast(poly->GetPointData()->GetNormals());
    furPoints(positions, normals, s.velocities, mesh, s.length, s.dynamics, vectorRows(pointArray));
    furNormals(normals, mesh, vectorRows(normalArray));
    points->Modified();
    normalArray->Modified();
    poly->Modified();
  };
  place(s.shells, s.shellPoly);
  if (s.finPoly) place(s.fins, s.finPoly);
}

}  // namespace tetskin
