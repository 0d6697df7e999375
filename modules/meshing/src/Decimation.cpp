// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/Decimation.h"

#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>

#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {

SurfaceMesh decimateSurface(const SurfaceMesh& surface, Index targetTriangles) {
  if (surface.triangleCount() == 0) throw Error("cannot decimate an empty surface");
  if (targetTriangles >= surface.triangleCount()) return surface;
  auto decimation = vtkSmartPointer<vtkQuadricDecimation>::New();
  SurfaceMesh positionsOnly;
  positionsOnly.positions = surface.positions;
  positionsOnly.triangles = surface.triangles;
  decimation->SetInputData(toVtkPolyData(positionsOnly));
  decimation->SetTargetReduction(1.0 - static_cast<double>(targetTriangles) /
                                           static_cast<double>(surface.triangleCount()));
  decimation->VolumePreservationOn();
  decimation->Update();
  return fromVtkPolyData(decimation->GetOutput(), "decimated surface");
}

std::vector<SurfaceMesh> decimatedSeries(const SurfaceMesh& finest, double factor,
                                         Index minTriangles, int maxCount) {
  std::vector<SurfaceMesh> series;
  double target = static_cast<double>(finest.triangleCount()) * factor;
  while (static_cast<int>(series.size()) < maxCount &&
         target >= static_cast<double>(minTriangles)) {
    // Decimating the original each time (not the previous copy) avoids
    // accumulating error.
    series.push_back(decimateSurface(finest, static_cast<Index>(target)));
    target *= factor;
  }
  return series;
}

}  // namespace tetskin
