// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtkTetSkinBufferMapper.h"

#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>

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

void vtkTetSkinBufferMapper::SetTexelLimit(vtkIdType texels) {
  this->TexelLimit = texels;
  this->Modified();
}

bool vtkTetSkinBufferMapper::UploadTexels(int k, const std::vector<float>& values,
                                          const std::function<std::string()>& what) {
  const auto texels = static_cast<vtkIdType>(values.size() / 4);
  if (this->GLTexelLimit == 0) {
    GLint queried = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &queried);
    this->GLTexelLimit = queried;
  }
  const vtkIdType limit = this->TexelLimit > 0
                              ? std::min<vtkIdType>(this->TexelLimit, this->GLTexelLimit)
                              : this->GLTexelLimit;
  if (texels > limit) {
    // Past the limit texel fetches read zeros (or worse): refuse instead.
    this->ReportGpuProblem(what() + " need " + std::to_string(texels) +
                           " texels in one texture buffer, more than the " + std::to_string(limit) +
                           " this OpenGL allows" +
                           (limit < this->GLTexelLimit ? " (the texel limit set)" : "") +
                           ": draw it with the cpu path");
    return false;
  }
  this->Buffers[k]->Upload(values, vtkOpenGLBufferObject::TextureBuffer);
  // RGB32F texture buffers need GL 4.0: 4 floats per texel.
  this->Textures[k]->CreateTextureBuffer(static_cast<unsigned int>(texels), 4, VTK_FLOAT,
                                         this->Buffers[k]);
  return true;
}

void vtkTetSkinBufferMapper::ReportGpuProblem(const std::string& problem) {
  if (!this->GpuProblem.empty()) return;
  this->GpuProblem = problem;
  vtkErrorMacro(<< problem);
}

void vtkTetSkinBufferMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  for (auto& texture : this->Textures) texture->SetContext(window);
  this->PrepareBuffers(window);
  this->Superclass::RenderPieceStart(ren, act);
  for (auto& texture : this->Textures)
    if (texture->GetHandle()) texture->Activate();
}

void vtkTetSkinBufferMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act) {
  if (this->GpuProblem.empty()) this->Superclass::RenderPieceDraw(ren, act);
}

void vtkTetSkinBufferMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
  for (auto& texture : this->Textures)
    if (texture->GetHandle()) texture->Deactivate();
  this->Superclass::RenderPieceFinish(ren, act);
}

void vtkTetSkinBufferMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->GLTexelLimit = 0;  // the next context may allow another
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

void vtkTetSkinBufferMapper::SetModelOrigin(const double origin[3]) {
  std::copy(origin, origin + 3, this->ModelOrigin);
  this->Modified();
}

void vtkTetSkinBufferMapper::SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                       vtkActor* act) {
  this->Superclass::SetCameraShaderParameters(cellBO, ren, act);
  tetskin::detail::useModelOrigin(cellBO.Program, ren, act, this->ModelOrigin);
}
