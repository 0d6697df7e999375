// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The fur over a deformable surface (report section 5): box texture
// coordinates, the procedural fur texture, shells and optional fins, as
// translucent actors drawn after the skin. fur-cpu places every fur vertex
// on the CPU each frame (update()); fur-gpu extrudes them in the vertex
// shader from the skin a vtkTetSkinGpu2PassMapper deformed on the GPU.

#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <memory>
#include <vector>

#include "tetskin/core/Appearance.h"
#include "tetskin/core/SurfaceMesh.h"

class vtkActor;
class vtkImageData;
class vtkRenderer;
class vtkTetSkinGpu2PassMapper;

namespace tetskin {

class FurLayer {
 public:
  // `rest`: the surface the fur grows on (its texcoords address
  // `colorTexture`, which may be null). `gpuSkin`: the skin's gpu-2pass
  // mapper for fur-gpu, null for fur-cpu. Throws Error on bad parameters.
  FurLayer(const SurfaceMesh& rest, const FurParameters& fur, const Material& material,
           vtkImageData* colorTexture, vtkTetSkinGpu2PassMapper* gpuSkin);
  ~FurLayer();

  // Shells, then fins; the renderer also gives the camera for adaptive shells.
  void addTo(vtkRenderer* renderer);
  std::vector<vtkActor*> actors() const;

  // Seconds between two updates (velocities of dynamic fur); default 1/60.
  void setFrameSeconds(double seconds);
  // fur-cpu: the deformed skin of this frame (positions, unit normals).
  void update(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals);
  // Fur length in model units.
  double length() const;
  // Shells drawn in the last frame (fur-gpu: as of the last render).
  int shellsDrawn() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
