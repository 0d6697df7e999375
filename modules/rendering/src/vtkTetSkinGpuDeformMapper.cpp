// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/vtkTetSkinGpuDeformMapper.h"

#include <vtkDataObject.h>
#include <vtkObjectFactory.h>

#include "tetskin/shaders/Shaders.h"

vtkStandardNewMacro(vtkTetSkinGpuDeformMapper)

vtkTetSkinGpuDeformMapper::vtkTetSkinGpuDeformMapper()
    : vtkTetSkinBufferMapper(tetskin::shaders::kGpuDeformDeclarationsVs,
                             tetskin::shaders::kGpuDeformImplVs, "tetskinControlPositions",
                             "tetskinControlNormals") {
  this->MapDataArrayToVertexAttribute("tetskinControlIds", "ControlIds",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute("tetskinWeights", "Weights",
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute("tetskinShift", kShiftArray,
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void vtkTetSkinGpuDeformMapper::SetEmbedBinding(bool embed) {
  if (embed) {
    this->SetShaderCode(tetskin::shaders::kGpuDeformEmbedDeclarationsVs,
                        tetskin::shaders::kGpuDeformEmbedImplVs);
    this->MapDataArrayToVertexAttribute("tetskinRestFrameNormal", kRestFrameNormalArray,
                                        vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  } else {
    this->SetShaderCode(tetskin::shaders::kGpuDeformDeclarationsVs,
                        tetskin::shaders::kGpuDeformImplVs);
    this->RemoveVertexAttributeMapping("tetskinRestFrameNormal");
  }
}

void vtkTetSkinGpuDeformMapper::SetControlState(const float* positions, const float* normals,
                                                vtkIdType nodes) {
  this->Positions.assign(static_cast<std::size_t>(4 * nodes), 0.0f);
  this->Normals.assign(normals ? static_cast<std::size_t>(4 * nodes) : 0, 0.0f);
  for (vtkIdType v = 0; v < nodes; ++v)
    for (int k = 0; k < 3; ++k) {
      this->Positions[static_cast<std::size_t>(4 * v + k)] = positions[3 * v + k];
      if (normals) this->Normals[static_cast<std::size_t>(4 * v + k)] = normals[3 * v + k];
    }
  this->StateChanged = true;
  this->Modified();
}

void vtkTetSkinGpuDeformMapper::PrepareBuffers(vtkOpenGLRenderWindow*) {
  if (!this->StateChanged || this->Positions.empty()) return;
  this->UploadTexels(0, this->Positions);
  if (!this->Normals.empty()) this->UploadTexels(1, this->Normals);
  this->StateChanged = false;
}

void vtkTetSkinGpuDeformMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->StateChanged = true;  // upload again into fresh buffers
  this->Superclass::ReleaseGraphicsResources(window);
}
