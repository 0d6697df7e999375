// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/vtkTetSkinBufferMapper.h"

#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "ShaderInjection.h"

vtkTetSkinBufferMapper::vtkTetSkinBufferMapper(const char* declarations, const char* implementation,
                                               const char* firstSampler, const char* secondSampler)
    : Declarations(declarations),
      Implementation(implementation),
      Samplers{firstSampler, secondSampler} {
  // The shader computes positions: VTK's VBO shift/scale would apply to the
  // rest positions only and misplace the surface.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
}

vtkTetSkinBufferMapper::~vtkTetSkinBufferMapper() = default;

void vtkTetSkinBufferMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DeformedBounds: " << this->DeformedBounds[0] << " .. " << this->DeformedBounds[5]
     << "\n";
}

void vtkTetSkinBufferMapper::SetDeformedBounds(const double bounds[6]) {
  std::copy(bounds, bounds + 6, this->DeformedBounds);
  this->Modified();
}

void vtkTetSkinBufferMapper::ComputeBounds() {
  if (this->DeformedBounds[0] <= this->DeformedBounds[1]) {
    std::copy(this->DeformedBounds, this->DeformedBounds + 6, this->Bounds);
    return;
  }
  this->Superclass::ComputeBounds();
}

void vtkTetSkinBufferMapper::SetShaderCode(const char* declarations, const char* implementation,
                                           const char* secondSampler) {
  this->Declarations = declarations;
  this->Implementation = implementation;
  this->Samplers[1] = secondSampler;
  this->Modified();
}

vtkOpenGLBufferObject* vtkTetSkinBufferMapper::Buffer(int k) {
  return this->Buffers[k];
}
vtkTextureObject* vtkTetSkinBufferMapper::Texture(int k) {
  return this->Textures[k];
}

void vtkTetSkinBufferMapper::UploadTexels(int k, const std::vector<float>& values) {
  this->Buffers[k]->Upload(values, vtkOpenGLBufferObject::TextureBuffer);
  // RGB32F texture buffers need GL 4.0: 4 floats per texel.
  this->Textures[k]->CreateTextureBuffer(static_cast<unsigned int>(values.size() / 4), 4, VTK_FLOAT,
                                         this->Buffers[k]);
}

void vtkTetSkinBufferMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  for (auto& texture : this->Textures) texture->SetContext(window);
  this->PrepareBuffers(window);
  this->Superclass::RenderPieceStart(ren, act);
  for (auto& texture : this->Textures)
    if (texture->GetHandle()) texture->Activate();
}

void vtkTetSkinBufferMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
  for (auto& texture : this->Textures)
    if (texture->GetHandle()) texture->Deactivate();
  this->Superclass::RenderPieceFinish(ren, act);
}

void vtkTetSkinBufferMapper::ReleaseGraphicsResources(vtkWindow* window) {
  for (auto& texture : this->Textures) texture->ReleaseGraphicsResources(window);
  for (auto& buffer : this->Buffers) buffer->ReleaseGraphicsResources();
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkTetSkinBufferMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders,
                                                 vtkRenderer* ren, vtkActor* act) {
  tetskin::detail::insertVertexCode(shaders[vtkShader::Vertex], this->Declarations,
                                    this->Implementation);
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  tetskin::detail::useDeformedVertex(shaders[vtkShader::Vertex]);
}

void vtkTetSkinBufferMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                       vtkActor* act) {
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  if (cellBO.Program)
    for (int k = 0; k < 2; ++k)
      if (this->Textures[k]->GetHandle())
        cellBO.Program->SetUniformi(this->Samplers[k], this->Textures[k]->GetTextureUnit());
}
