// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtkTetSkinGpuFurMapper.h"

#include <vtkDataObject.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLIndexBufferObject.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "GpuContract.h"
#include "tetskin/fur/FurGeometry.h"
#include "tetskin/shaders/Shaders.h"
#include "vtkTetSkinGpu2PassMapper.h"

vtkStandardNewMacro(vtkTetSkinGpuFurMapper)

vtkTetSkinGpuFurMapper::vtkTetSkinGpuFurMapper() {
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kFurSource, "FurSource",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void vtkTetSkinGpuFurMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shells: " << this->MinShells << ".." << this->MaxShells
     << (this->Adaptive ? " adaptive" : "") << ", drawn " << this->ShellsDrawn << "\n";
}

void vtkTetSkinGpuFurMapper::SetSource(vtkTetSkinGpu2PassMapper* source) {
  this->Source = source;
  if (source) source->SetKeepPreviousPositions(true);
  this->Modified();
}

void vtkTetSkinGpuFurMapper::SetShells(int maxShells, int minShells, bool adaptive) {
  this->MaxShells = maxShells;
  this->MinShells = minShells;
  this->Adaptive = adaptive;
  this->Modified();
}

void vtkTetSkinGpuFurMapper::SetDynamics(double length, double frameSeconds, double drag,
                                         double maxBend, double minLift) {
  this->Length = static_cast<float>(length);
  this->FrameSeconds = static_cast<float>(frameSeconds);
  this->Drag = static_cast<float>(drag);
  this->MaxBend = static_cast<float>(maxBend);
  this->MinLift = static_cast<float>(minLift);
  this->Modified();
}

const char* vtkTetSkinGpuFurMapper::VertexDeclarations() const {
  return tetskin::shaders::kFurGpuDeclarationsVs;
}
const char* vtkTetSkinGpuFurMapper::VertexImplementation() const {
  return tetskin::shaders::kFurGpuImplVs;
}

void vtkTetSkinGpuFurMapper::ComputeBounds() {
  // The skin's deformed bounds grown by the fur length.
  if (!this->Source) {
    this->Superclass::ComputeBounds();
    return;
  }
  this->Source->GetBounds(this->Bounds);
  for (int k = 0; k < 3; ++k) {
    this->Bounds[2 * k] -= this->Length;
    this->Bounds[2 * k + 1] += this->Length;
  }
}

bool vtkTetSkinGpuFurMapper::SourceReady() const {
  // The skin renders first; when it could not fill its buffers, there is
  // nothing for the fur to read.
  return this->Source && this->Source->GetGpuProblem().empty();
}

void vtkTetSkinGpuFurMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act) {
  this->Superclass::RenderPieceStart(ren, act);
  if (!this->SourceReady()) return;
  this->Source->DeformedPositions()->Activate();
  this->Source->DeformedNormals()->Activate();
  this->Source->PreviousPositions()->Activate();
}

void vtkTetSkinGpuFurMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
  if (this->SourceReady()) {
    this->Source->PreviousPositions()->Deactivate();
    this->Source->DeformedNormals()->Deactivate();
    this->Source->DeformedPositions()->Deactivate();
  }
  this->Superclass::RenderPieceFinish(ren, act);
}

void vtkTetSkinGpuFurMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                       vtkActor* act) {
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* p = cellBO.Program;
  if (!p || !this->Source) return;
  p->SetUniformi("tetskinDeformedPositions", this->Source->DeformedPositions()->GetTextureUnit());
  p->SetUniformi("tetskinDeformedNormals", this->Source->DeformedNormals()->GetTextureUnit());
  p->SetUniformi("tetskinPreviousPositions", this->Source->PreviousPositions()->GetTextureUnit());
  p->SetUniformi("tetskinShellCount", this->ShellsDrawn);
  p->SetUniformf("tetskinFurLength", this->Length);
  p->SetUniformf("tetskinFrameSeconds", this->FrameSeconds);
  p->SetUniformf("tetskinDrag", this->Drag);
  p->SetUniformf("tetskinMaxBend", this->MaxBend);
  p->SetUniformf("tetskinMinLift", this->MinLift);
}

void vtkTetSkinGpuFurMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act) {
  vtkOpenGLHelper& tris = this->Primitives[PrimitiveTris];
  if (!this->SourceReady() || tris.IBO->IndexCount == 0) return;
  int instances = 1;
  if (this->MaxShells > 0) {
    instances = this->MaxShells;
    if (this->Adaptive)
      instances =
          tetskin::adaptiveShellCount(FurPixelHeight(ren, this->Source->GetBounds(), this->Length),
                                      this->MinShells, this->MaxShells);
    this->ShellsDrawn = instances;
  } else {
    this->ShellsDrawn = 0;
  }
  this->UpdateShaders(tris, ren, act);  // sets the uniforms, ShellsDrawn among them
  tris.IBO->Bind();
  // Instances are drawn in order: shell 1 (innermost) first, as blending needs.
  glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(tris.IBO->IndexCount), GL_UNSIGNED_INT,
                          nullptr, instances);
  tris.IBO->Release();
}
