// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A vtkOpenGLPolyDataMapper that deforms a bound surface on the GPU (the
// report's "GPU 1-pass", section 4.3): rest positions, control ids, weights
// and offsets are vertex attributes uploaded once; per frame only the
// control mesh's positions and vertex normals go to the GPU, as texture
// buffers; the vertex shader computes position and normal. It behaves like an
// ordinary mapper: bounds are the deformed surface's (camera reset, culling),
// and hardware picking sees the deformed surface.
//
// The input polydata must carry point arrays ControlIds (3), Weights (3),
// kShiftArray (4: x, y, z, d; the vertex is sum w_i X_i + (x, y, z) + d n, n
// the deformed control triangle's unit normal) and Normals (any: the shader
// replaces them). The normal is the control vertex normals interpolated with
// the weights (the report's method).
//
// With SetEmbedBinding(true), each vertex is bound to a tetrahedron instead:
// ControlIds (4), Weights (4), kShiftArray (x, y, z; d unused) and Normals
// (3: the rest surface's normals n); per frame SetEmbedState() gives
// the control nodes' normal transforms G (deformation NormalTransforms.h)
// instead of their normals, and the normal is (sum w_i G_i) n.

#include <vector>

#include "vtkTetSkinBufferMapper.h"

class vtkTetSkinGpuDeformMapper : public vtkTetSkinBufferMapper {
 public:
  static vtkTetSkinGpuDeformMapper* New();
  vtkTypeMacro(vtkTetSkinGpuDeformMapper, vtkTetSkinBufferMapper)

  static constexpr const char* kShiftArray = "TetSkinShift";

  // Triangle bindings (the default) or embed bindings (see above); set
  // before the first render.
  void SetEmbedBinding(bool embed);

  // Triangle bindings: control node positions and normals, xyz per node in
  // the dataset's numbering; uploaded at the next render.
  void SetControlState(const float* positions, const float* normals, vtkIdType nodes);
  // Embed bindings: positions as above and each node's normal transform, its
  // three columns (9 numbers per node).
  void SetEmbedState(const float* positions, const double* normalTransforms, vtkIdType nodes);
  void ReleaseGraphicsResources(vtkWindow* window) override;

 protected:
  vtkTetSkinGpuDeformMapper();
  ~vtkTetSkinGpuDeformMapper() override = default;
  void PrepareBuffers(vtkOpenGLRenderWindow* window) override;

 private:
  vtkTetSkinGpuDeformMapper(const vtkTetSkinGpuDeformMapper&) = delete;
  void operator=(const vtkTetSkinGpuDeformMapper&) = delete;
  void SetPositions(const float* positions, vtkIdType nodes);
  // xyz_ per node; Normals: for embed bindings three texels per node, the
  // columns of its normal transform.
  std::vector<float> Positions, Normals;
  bool StateChanged = false;
  bool Embed = false;
};
