// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtkTetSkinGpuDeformMapper.h"

#include <vtkDataObject.h>
#include <vtkObjectFactory.h>

#include <string>

#include "GpuContract.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/shaders/Shaders.h"

vtkStandardNewMacro(vtkTetSkinGpuDeformMapper)

namespace {
constexpr const char* kControlNormalsSampler = "tetskinControlNormals";
constexpr const char* kNormalTransformsSampler = "tetskinNormalTransforms";
}  // namespace

vtkTetSkinGpuDeformMapper::vtkTetSkinGpuDeformMapper()
    : vtkTetSkinBufferMapper(tetskin::shaders::kGpuDeformDeclarationsVs,
                             tetskin::shaders::kGpuDeformImplVs, "tetskinControlPositions",
                             kControlNormalsSampler) {
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kControlIds,
                                      tetskin::arrays::kControlIds,
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kWeights, tetskin::arrays::kWeights,
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kShift, kShiftArray,
                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void vtkTetSkinGpuDeformMapper::SetEmbedBinding(bool embed) {
  this->Embed = embed;
  if (embed) {
    this->SetShaderCode(tetskin::shaders::kGpuDeformEmbedDeclarationsVs,
                        tetskin::shaders::kGpuDeformEmbedImplVs, kNormalTransformsSampler);
    this->MapDataArrayToVertexAttribute(tetskin::gpu::attribute::kRestNormal,
                                        tetskin::arrays::kNormals,
                                        vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  } else {
    this->SetShaderCode(tetskin::shaders::kGpuDeformDeclarationsVs,
                        tetskin::shaders::kGpuDeformImplVs, kControlNormalsSampler);
    this->RemoveVertexAttributeMapping("tetskinRestNormal");
  }
}

void vtkTetSkinGpuDeformMapper::SetControlState(const float* positions, const float* normals,
                                                vtkIdType nodes) {
  this->SetPositions(positions, nodes);
  this->Normals.assign(normals ? static_cast<std::size_t>(4 * nodes) : 0, 0.0f);
  if (normals)
    for (vtkIdType v = 0; v < nodes; ++v)
      for (int k = 0; k < 3; ++k)
        this->Normals[static_cast<std::size_t>(4 * v + k)] = normals[3 * v + k];
}

void vtkTetSkinGpuDeformMapper::SetEmbedState(const float* positions,
                                              const double* normalTransforms, vtkIdType nodes) {
  this->SetPositions(positions, nodes);
  this->Normals.assign(static_cast<std::size_t>(12 * nodes), 0.0f);
  for (vtkIdType c = 0; c < 3 * nodes; ++c)  // a column of a node's G per texel
    for (int k = 0; k < 3; ++k)
      this->Normals[static_cast<std::size_t>(4 * c + k)] =
          static_cast<float>(normalTransforms[3 * c + k]);
}

void vtkTetSkinGpuDeformMapper::SetPositions(const float* positions, vtkIdType nodes) {
  this->Positions.assign(static_cast<std::size_t>(4 * nodes), 0.0f);
  for (vtkIdType v = 0; v < nodes; ++v)
    for (int k = 0; k < 3; ++k)
      this->Positions[static_cast<std::size_t>(4 * v + k)] = positions[3 * v + k];
  this->StateChanged = true;
  this->Modified();
}

void vtkTetSkinGpuDeformMapper::PrepareBuffers(vtkOpenGLRenderWindow*) {
  if (!this->StateChanged || this->Positions.empty() || !this->GetGpuProblem().empty()) return;
  const auto nodes = [this] {
    return std::to_string(this->Positions.size() / 4) + " control nodes";
  };
  if (!this->UploadTexels(0, this->Positions,
                          [&] { return "gpu-1pass: the positions of " + nodes(); }))
    return;
  if (!this->Normals.empty() && !this->UploadTexels(1, this->Normals, [&] {
        return this->Embed ? "gpu-1pass: the normal transforms of " + nodes() + " (3 texels each)"
                           : "gpu-1pass: the normals of " + nodes();
      }))
    return;
  this->StateChanged = false;
}

void vtkTetSkinGpuDeformMapper::ReleaseGraphicsResources(vtkWindow* window) {
  this->StateChanged = true;  // upload again into fresh buffers
  this->Superclass::ReleaseGraphicsResources(window);
}
