// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The report's "GPU 2-pass" in modern form: a first pass of compute shaders
// writes the exact deformed positions and smooth normals of every surface
// vertex into GPU buffers (positions; area-weighted face normals; a one-ring
// gather per vertex, no atomics); the draw pass reads them through texture
// buffers. Static data (binding, triangles, one-ring) is uploaded once; per
// frame only the control node positions. Needs OpenGL 4.3.

#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>

#include <vector>

class vtkOpenGLBufferObject;
class vtkTextureObject;
class vtkRenderWindow;

class vtkTetSkinGpu2PassMapper : public vtkOpenGLPolyDataMapper {
 public:
  static vtkTetSkinGpu2PassMapper* New();
  vtkTypeMacro(vtkTetSkinGpu2PassMapper,
               vtkOpenGLPolyDataMapper) void PrintSelf(ostream& os, vtkIndent indent) override;

  // Per surface vertex: 3 control ids, 3 weights + the normal offset d;
  // triangles (3 ids each) and the one-ring (offsets: vertices + 1 entries).
  void SetSurface(const std::vector<int>& controlIds, const std::vector<float>& weightsAndOffset,
                  const std::vector<int>& triangles, const std::vector<int>& ringOffsets,
                  const std::vector<int>& ringFaces);
  // Control node positions, xyz per node (dataset numbering); used at the next render.
  void SetControlPositions(const float* positions, vtkIdType nodes);
  void SetDeformedBounds(const double bounds[6]);
  // The positions the first pass computed, xyzw per vertex (reads GPU memory).
  std::vector<float> ReadDeformedPositions(vtkRenderWindow* window);

  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

 protected:
  vtkTetSkinGpu2PassMapper();
  ~vtkTetSkinGpu2PassMapper() override;
  void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                           vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

 private:
  vtkTetSkinGpu2PassMapper(const vtkTetSkinGpu2PassMapper&) = delete;
  void operator=(const vtkTetSkinGpu2PassMapper&) = delete;
  void ComputePass();

  struct GpuState;
  GpuState* Gpu;
  std::vector<int> Ids, Triangles, RingOffsets, RingFaces;  // ids and triangles padded to 4
  std::vector<float> Weights;
  std::vector<float> Control;  // xyz_ per node
  vtkIdType Vertices = 0, TriangleCount = 0, Nodes = 0;
  bool SurfaceChanged = false, ControlChanged = false;
  double DeformedBounds[6] = {0, -1, 0, -1, 0, -1};
  vtkNew<vtkOpenGLBufferObject> PositionBuffer, NormalBuffer;
  vtkNew<vtkTextureObject> PositionTexture, NormalTexture;
};
