// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtkTetSkinFurMapper.h"

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "GpuContract.h"
#include "ShaderInjection.h"
#include "tetskin/shaders/Shaders.h"

vtkStandardNewMacro(vtkTetSkinFurMapper)

namespace {

// Unit direction toward the renderer's first switched-on light, in view
// coordinates (a headlight shines from the camera: +z).
void lightDirectionVC(vtkRenderer* ren, float out[3]) {
  out[0] = 0;
  out[1] = 0;
  out[2] = 1;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it)) {
    if (!light->GetSwitch()) continue;
    if (light->LightTypeIsHeadlight()) return;
    double d[3];
    for (int k = 0; k < 3; ++k) d[k] = light->GetPosition()[k] - light->GetFocalPoint()[k];
    if (light->LightTypeIsSceneLight()) {
      vtkMatrix4x4* view = ren->GetActiveCamera()->GetViewTransformMatrix();
      double v[3];
      for (int r = 0; r < 3; ++r)
        v[r] = view->GetElement(r, 0) * d[0] + view->GetElement(r, 1) * d[1] +
               view->GetElement(r, 2) * d[2];
      std::copy(v, v + 3, d);
    }
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (n > 0)
      for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(d[k] / n);
    return;
  }
}

}  // namespace

vtkTetSkinFurMapper::vtkTetSkinFurMapper() {
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kFurTCoords, "FurTCoords",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kFurHeight, "FurHeight",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kColorTCoords, "ColorTCoords",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->ScalarVisibilityOff();
  this->SetColorTexture(nullptr);
}

vtkTetSkinFurMapper::~vtkTetSkinFurMapper() = default;

void vtkTetSkinFurMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FurTexture: " << this->FurSize << "^2 x " << this->FurLayers
     << ", Fins: " << this->Fins << ", KajiyaKay: " << this->KajiyaKay << "\n";
}

void vtkTetSkinFurMapper::SetFurTexture(int size, int layers,
                                        const std::vector<std::uint8_t>& rgba) {
  this->FurSize = size;
  this->FurLayers = layers;
  this->FurTexels = rgba;
  this->FurDirty = true;
  this->Modified();
}

void vtkTetSkinFurMapper::SetColorTexture(vtkImageData* image) {
  if (image) {
    this->ColorImage = image;
  } else {  // one white texel: no tint, no mask
    this->ColorImage = vtkSmartPointer<vtkImageData>::New();
    this->ColorImage->SetDimensions(1, 1, 1);
    this->ColorImage->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    auto* p = static_cast<unsigned char*>(this->ColorImage->GetScalarPointer());
    std::fill(p, p + 4, 255);
  }
  this->ColorDirty = true;
  this->Modified();
}

void vtkTetSkinFurMapper::SetFins(bool fins) {
  this->Fins = fins;
  this->Modified();
}
void vtkTetSkinFurMapper::SetKajiyaKay(bool kajiyaKay) {
  this->KajiyaKay = kajiyaKay;
  this->Modified();
}
void vtkTetSkinFurMapper::SetVelvet(double velvet) {
  this->Velvet = static_cast<float>(velvet);
  this->Modified();
}
void vtkTetSkinFurMapper::SetTint(const std::array<double, 3>& rgb) {
  for (int k = 0; k < 3; ++k)
    this->Tint[static_cast<std::size_t>(k)] = static_cast<float>(rgb[static_cast<std::size_t>(k)]);
  this->Modified();
}

const char* vtkTetSkinFurMapper::VertexDeclarations() const {
  return "";
}
const char* vtkTetSkinFurMapper::VertexImplementation() const {
  return tetskin::shaders::kFurCpuImplVs;
}

void vtkTetSkinFurMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders,
                                              vtkRenderer* ren, vtkActor* act) {
  const std::string declarations = std::string(tetskin::shaders::kFurDeclarationsVs) +
                                   this->VertexDeclarations() + "\n//VTK::CustomUniforms::Dec\n";
  const std::string implementation =
      std::string(this->VertexImplementation()) + "\n//VTK::CustomBegin::Impl\n";
  tetskin::detail::insertVertexCode(shaders[vtkShader::Vertex], declarations.c_str(),
                                    implementation.c_str());
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(
      fs, "//VTK::CustomUniforms::Dec",
      std::string(tetskin::shaders::kFurDeclarationsFs) + "\n//VTK::CustomUniforms::Dec");
  shaders[vtkShader::Fragment]->SetSource(fs);
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  tetskin::detail::useDeformedVertex(shaders[vtkShader::Vertex]);
  // After VTK's lighting: the fur's replaces its colour.
  fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl", tetskin::shaders::kFurLightingFs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

void vtkTetSkinFurMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                    vtkActor* act) {
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* p = cellBO.Program;
  if (!p) return;
  p->SetUniformi("tetskinFurTexture", this->FurTexture->GetTextureUnit());
  p->SetUniformi("tetskinColorTexture", this->ColorTexture->GetTextureUnit());
  p->SetUniformi("tetskinHasColorTexture", 1);
  p->SetUniformi("tetskinFins", this->Fins ? 1 : 0);
  p->SetUniformi("tetskinKajiyaKay", this->KajiyaKay ? 1 : 0);
  p->SetUniformf("tetskinVelvet", this->Velvet);
  float light[3];
  lightDirectionVC(ren, light);
  p->SetUniform3f("tetskinLightVC", light);
  p->SetUniform3f("tetskinFurTint", this->Tint.data());
}

void vtkTetSkinFurMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->FurTexture->SetContext(window);
  this->ColorTexture->SetContext(window);
  if (this->FurDirty && !this->FurTexels.empty()) {
    this->FurTexture->SetWrapS(vtkTextureObject::Repeat);
    this->FurTexture->SetWrapT(vtkTextureObject::Repeat);
    this->FurTexture->SetWrapR(vtkTextureObject::ClampToEdge);
    this->FurTexture->SetMinificationFilter(vtkTextureObject::Linear);
    this->FurTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    this->FurTexture->Create3DFromRaw(
        static_cast<unsigned>(this->FurSize), static_cast<unsigned>(this->FurSize),
        static_cast<unsigned>(this->FurLayers), 4, VTK_UNSIGNED_CHAR, this->FurTexels.data());
    this->FurDirty = false;
  }
  if (this->ColorDirty) {
    int dims[3];
    this->ColorImage->GetDimensions(dims);
    this->ColorTexture->SetWrapS(vtkTextureObject::Repeat);
    this->ColorTexture->SetWrapT(vtkTextureObject::Repeat);
    this->ColorTexture->SetMinificationFilter(vtkTextureObject::Linear);
    this->ColorTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    this->ColorTexture->Create2DFromRaw(static_cast<unsigned>(dims[0]),
                                        static_cast<unsigned>(dims[1]),
                                        this->ColorImage->GetNumberOfScalarComponents(),
                                        VTK_UNSIGNED_CHAR, this->ColorImage->GetScalarPointer());
    this->ColorDirty = false;
  }
  this->Superclass::RenderPieceStart(ren, act);
  this->FurTexture->Activate();
  this->ColorTexture->Activate();
}

void vtkTetSkinFurMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
  this->ColorTexture->Deactivate();
  this->FurTexture->Deactivate();
  this->Superclass::RenderPieceFinish(ren, act);
}

void vtkTetSkinFurMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->FurTexture->ReleaseGraphicsResources(window);
  this->ColorTexture->ReleaseGraphicsResources(window);
  this->FurDirty = this->ColorDirty = true;
  this->Superclass::ReleaseGraphicsResources(window);
}

double vtkTetSkinFurMapper::FurPixelHeight(vtkRenderer* ren, const double bounds[6],
                                           double length) {
  vtkCamera* camera = ren->GetActiveCamera();
  const int* size = ren->GetSize();
  if (!camera || !size || size[1] <= 0) return 0;
  if (camera->GetParallelProjection()) return length * size[1] / (2.0 * camera->GetParallelScale());
  double distance = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = camera->GetPosition()[k] - 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    distance += d * d;
  }
  distance = std::max(std::sqrt(distance), 1e-12);
  const double halfAngle = 0.5 * camera->GetViewAngle() * M_PI / 180.0;
  return length * size[1] / (2.0 * distance * std::tan(halfAngle));
}

void vtkTetSkinFurMapper::SetModelOrigin(const double origin[3]) {
  std::copy(origin, origin + 3, this->ModelOrigin);
  this->Modified();
}

void vtkTetSkinFurMapper::SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                    vtkActor* act) {
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  tetskin::detail::useModelOrigin(cellBO.Program, ren, act, this->ModelOrigin);
}
