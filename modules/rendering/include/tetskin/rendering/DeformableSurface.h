// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A bound surface as a VTK actor that follows the control mesh, drawn by one
// of the render paths. update() takes the control state of a frame; the
// actor is then ready to render.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <memory>
#include <string>

#include "tetskin/core/Appearance.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/rendering/FurLayer.h"
#include "tetskin/rendering/RenderPath.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace tetskin {

struct FrameTimes {
  double deformSeconds = 0;  // CPU deformation (cpu path) or control normals (gpu paths)
  double uploadSeconds = 0;  // handing data to VTK / the GPU buffers
};

class DeformableSurface {
 public:
  // `restSurface` and `binding` as from tetskin bind (triangle methods);
  // `dataset` gives the rest nodes (dataset numbering). A `texture` (PNG)
  // colours the surface through its texture coordinates (the report's
  // "BunnyTex"); on the fur paths it colours and masks the fur instead
  // (alpha 0: no fur) and the skin is drawn darkened, with a weaker, broader
  // highlight. Throws Error when the surface has no texture coordinates or
  // the file is bad.
  DeformableSurface(const MultiLevelTetMesh& dataset, const SurfaceMesh& restSurface,
                    const SurfaceBinding& binding, RenderPath path, const Material& material,
                    const std::filesystem::path& texture = {}, const FurParameters& fur = {});
  ~DeformableSurface();

  RenderPath path() const;
  // The skin (what picking hits).
  vtkActor* actor() const;
  // Adds the skin and, on fur paths, the fur after it.
  void addTo(vtkRenderer* renderer);
  // The fur of the fur paths, else null.
  FurLayer* fur() const;
  // Seconds between updates, for the velocities of dynamic fur (default 1/60).
  void setFrameSeconds(double seconds);
  // The polydata VTK draws (deformed on the cpu path, at rest on gpu paths).
  vtkPolyData* polyData() const;
  // Control state in the dataset's numbering.
  FrameTimes update(const Points3& controlPositions);
  // Bounds of the deformed surface of the last update (xmin, xmax, ...).
  const double* bounds() const;
  // After a render: why a gpu path could not draw this surface on this
  // OpenGL (vtkTetSkinBufferMapper::GetGpuProblem), or empty.
  std::string gpuProblem() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
