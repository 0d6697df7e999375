// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The report's "GPU 2-pass" in modern form: a first pass of compute shaders
// writes the exact deformed positions and smooth normals of every surface
// vertex into GPU buffers (positions; area-weighted face normals; a one-ring
// gather per vertex, no atomics); the draw pass reads them through texture
// buffers. Static data (binding, triangles, one-ring) is uploaded once; per
// frame only the control node positions. Needs OpenGL 4.3.

#include <vector>

#include "vtkTetSkinBufferMapper.h"

class vtkRenderWindow;
class vtkTextureObject;

class vtkTetSkinGpu2PassMapper : public vtkTetSkinBufferMapper {
 public:
  static vtkTetSkinGpu2PassMapper* New();
  vtkTypeMacro(vtkTetSkinGpu2PassMapper, vtkTetSkinBufferMapper)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Per surface vertex, 4 values each: control ids (the 4th -1 for a
  // triangle binding), weights (the 4th 0 for a triangle), and a shift
  // (x, y, z, d): the vertex is sum w_i X_i + (x, y, z) + d n, n the unit
  // normal of the deformed control triangle (triangle bindings only). Then
  // the triangles (3 ids each) and the one-ring (offsets: vertices + 1).
  void SetSurface(const std::vector<int>& controlIds, const std::vector<float>& weights,
                  const std::vector<float>& shifts, const std::vector<int>& triangles,
                  const std::vector<int>& ringOffsets, const std::vector<int>& ringFaces);
  // Control node positions, xyz per node (dataset numbering); used at the next render.
  void SetControlPositions(const float* positions, vtkIdType nodes);
  // The positions the first pass computed, xyzw per vertex, in model
  // coordinates (reads GPU memory; adds the model origin back).
  std::vector<float> ReadDeformedPositions(vtkRenderWindow* window);

  void ReleaseGraphicsResources(vtkWindow* window) override;

  // What later draws of the same frame (fur-gpu) read: texture buffers of
  // xyzw per vertex, valid after this mapper rendered. With
  // KeepPreviousPositions on, PreviousPositions() holds the positions of the
  // control state set before the last one (equal on the first), so velocities
  // are those between the last two SetControlPositions, as on the CPU.
  void SetKeepPreviousPositions(bool keep);
  vtkTextureObject* DeformedPositions();
  vtkTextureObject* DeformedNormals();
  vtkTextureObject* PreviousPositions();

 protected:
  vtkTetSkinGpu2PassMapper();
  ~vtkTetSkinGpu2PassMapper() override;
  // The compute pass, before every draw.
  void PrepareBuffers(vtkOpenGLRenderWindow* window) override;

 private:
  void ComputePreviousPositions(vtkOpenGLRenderWindow* window);
  vtkTetSkinGpu2PassMapper(const vtkTetSkinGpu2PassMapper&) = delete;
  void operator=(const vtkTetSkinGpu2PassMapper&) = delete;

  struct GpuState;
  GpuState* Gpu;
  std::vector<int> Ids, Triangles, RingOffsets, RingFaces;  // triangles padded to 4
  std::vector<float> Weights, Shifts;
  std::vector<float> Control;  // xyz_ per node
  vtkIdType Vertices = 0, TriangleCount = 0, Nodes = 0;
  bool SurfaceChanged = false, ControlChanged = false;
  bool KeepPrevious = false;
  std::vector<float> PreviousControl;  // xyz_ per node, the state before Control
};
