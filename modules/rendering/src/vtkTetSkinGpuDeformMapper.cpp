// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/vtkTetSkinGpuDeformMapper.h"

#include <vtkDataObject.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "tetskin/shaders/Shaders.h"

vtkStandardNewMacro(vtkTetSkinGpuDeformMapper)

    vtkTetSkinGpuDeformMapper::vtkTetSkinGpuDeformMapper() {
  // The shader computes positions from the binding: VTK's VBO shift/scale
  // would apply to the rest positions only and misplace the surface.
  this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  this->MapDataArrayToVertexAttribute("tetskinControlIds", "ControlIds",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute("tetskinWeights", "Weights",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute("tetskinDistance", "Distance",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

vtkTetSkinGpuDeformMapper::~vtkTetSkinGpuDeformMapper() = default;

void vtkTetSkinGpuDeformMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ControlNodes: " << this->Nodes << "\n";
}

void vtkTetSkinGpuDeformMapper::SetControlState(const float* positions, const float* normals,
                                                vtkIdType nodes) {
  this->Nodes = nodes;
  this->Positions.assign(static_cast<std::size_t>(4 * nodes), 0.0f);
  this->Normals.assign(static_cast<std::size_t>(4 * nodes), 0.0f);
  // RGB32F texture buffers need GL 4.0: pad to 4 floats per texel.
  for (vtkIdType v = 0; v < nodes; ++v)
    for (int k = 0; k < 3; ++k) {
      this->Positions[static_cast<std::size_t>(4 * v + k)] = positions[3 * v + k];
      this->Normals[static_cast<std::size_t>(4 * v + k)] = normals[3 * v + k];
    }
  this->StateChanged = true;
  this->Modified();
}

void vtkTetSkinGpuDeformMapper::SetDeformedBounds(const double bounds[6]) {
  std::copy(bounds, bounds + 6, this->DeformedBounds);
  this->Modified();
}

void vtkTetSkinGpuDeformMapper::ComputeBounds() {
  if (this->DeformedBounds[0] <= this->DeformedBounds[1]) {
    std::copy(this->DeformedBounds, this->DeformedBounds + 6, this->Bounds);
    return;
  }
  this->Superclass::ComputeBounds();
}

void vtkTetSkinGpuDeformMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act) {
  this->Superclass::RenderPieceStart(ren, act);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (this->StateChanged && this->Nodes > 0) {
    this->PositionTexture->SetContext(window);
    this->NormalTexture->SetContext(window);
    this->PositionBuffer->Upload(this->Positions, vtkOpenGLBufferObject::TextureBuffer);
    this->NormalBuffer->Upload(this->Normals, vtkOpenGLBufferObject::TextureBuffer);
    this->PositionTexture->CreateTextureBuffer(static_cast<unsigned int>(this->Nodes), 4, VTK_FLOAT,
                                               this->PositionBuffer);
    this->NormalTexture->CreateTextureBuffer(static_cast<unsigned int>(this->Nodes), 4, VTK_FLOAT,
                                             this->NormalBuffer);
    this->StateChanged = false;
  }
  this->PositionTexture->Activate();
  this->NormalTexture->Activate();
}

void vtkTetSkinGpuDeformMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
  this->PositionTexture->Deactivate();
  this->NormalTexture->Deactivate();
  this->Superclass::RenderPieceFinish(ren, act);
}

void vtkTetSkinGpuDeformMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->PositionTexture->ReleaseGraphicsResources(window);
  this->NormalTexture->ReleaseGraphicsResources(window);
  this->PositionBuffer->ReleaseGraphicsResources();
  this->NormalBuffer->ReleaseGraphicsResources();
  this->StateChanged = true;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkTetSkinGpuDeformMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders,
                                                    vtkRenderer* ren, vtkActor* act) {
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  vtkShaderProgram::Substitute(vs, "//VTK::CustomUniforms::Dec",
                               tetskin::shaders::kGpuDeformDeclarationsVs);
  vtkShaderProgram::Substitute(vs, "//VTK::CustomBegin::Impl", tetskin::shaders::kGpuDeformImplVs);
  shaders[vtkShader::Vertex]->SetSource(vs);
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  // After VTK's own substitutions: use the deformed position and normal.
  vs = shaders[vtkShader::Vertex]->GetSource();
  vtkShaderProgram::Substitute(vs, "* vertexMC", "* deformedMC", true);
  vtkShaderProgram::Substitute(vs, "normalMatrix * normalMC", "normalMatrix * deformedNormalMC",
                               true);
  shaders[vtkShader::Vertex]->SetSource(vs);
}

void vtkTetSkinGpuDeformMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                          vtkActor* act) {
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  if (cellBO.Program) {
    cellBO.Program->SetUniformi("tetskinControlPositions", this->PositionTexture->GetTextureUnit());
    cellBO.Program->SetUniformi("tetskinControlNormals", this->NormalTexture->GetTextureUnit());
  }
}
