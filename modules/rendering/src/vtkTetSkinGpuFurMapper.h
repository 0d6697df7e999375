// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// fur-gpu: fur vertices are extruded in the vertex shader from the surface a
// vtkTetSkinGpu2PassMapper deformed in the same frame (its positions, smooth
// normals and last frame's positions, read as texture buffers), with the
// dynamic-fur shift of tetskin::furShellOffset. Shells are drawn with one
// instanced draw, instance i at height (i + 1) / shells, inside out; with a
// shell count of 0 the input is drawn once at its FurHeight (fins).
// The input carries the fur attributes of vtkTetSkinFurMapper plus FurSource
// (1: the unsplit surface vertex each fur vertex grows from).

#include <vtkWeakPointer.h>

#include "vtkTetSkinFurMapper.h"

class vtkTetSkinGpu2PassMapper;

class vtkTetSkinGpuFurMapper : public vtkTetSkinFurMapper {
 public:
  static vtkTetSkinGpuFurMapper* New();
  vtkTypeMacro(vtkTetSkinGpuFurMapper, vtkTetSkinFurMapper)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The mapper of the skin, drawn before this one (keeps previous positions).
  void SetSource(vtkTetSkinGpu2PassMapper* source);
  // The most shells, and the least when adaptive (0 = fins, one plain draw).
  void SetShells(int maxShells, int minShells, bool adaptive);
  void SetDynamics(double length, double frameSeconds, double drag, double maxBend, double minLift);
  // Shells of the last draw.
  int GetShellsDrawn() const { return this->ShellsDrawn; }

  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;

 protected:
  vtkTetSkinGpuFurMapper();
  ~vtkTetSkinGpuFurMapper() override = default;
  const char* VertexDeclarations() const override;
  const char* VertexImplementation() const override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

 private:
  vtkTetSkinGpuFurMapper(const vtkTetSkinGpuFurMapper&) = delete;
  void operator=(const vtkTetSkinGpuFurMapper&) = delete;
  bool SourceReady() const;
  vtkWeakPointer<vtkTetSkinGpu2PassMapper> Source;
  int MaxShells = 16, MinShells = 4, ShellsDrawn = 0;
  bool Adaptive = false;
  float Length = 0, FrameSeconds = 0, Drag = 0, MaxBend = 0.6f, MinLift = 0.35f;
};
