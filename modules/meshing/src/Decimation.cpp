// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/Decimation.h"

#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>

#include "tetskin/core/Error.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {

SurfaceMesh decimateSurface(const SurfaceMesh& surface, Index targetTriangles) {
  if (surface.triangleCount() == 0) throw Error("cannot decimate an empty surface");
  if (targetTriangles >= surface.triangleCount()) return surface;
  auto decimation = vtkSmartPointer<vtkQuadricDecimation>::New();
  // Decimated about its own centre: the quadrics hold plane offsets n . p,
  // which for a model far from the origin (1e6 away, say, in a site's
  // coordinates) swamp the shape's own size, and the result was torn.
  const Eigen::RowVector3d center = boundingBox(surface).center().transpose();
  SurfaceMesh positionsOnly;
  positionsOnly.positions = surface.positions.rowwise() - center;
  positionsOnly.triangles = surface.triangles;
  decimation->SetInputData(toVtkPolyData(positionsOnly));
  decimation->SetTargetReduction(1.0 - static_cast<double>(targetTriangles) /
                                           static_cast<double>(surface.triangleCount()));
  decimation->VolumePreservationOn();
  decimation->Update();
  SurfaceMesh decimated = fromVtkPolyData(decimation->GetOutput(), "decimated surface");
  decimated.positions.rowwise() += center;
  return decimated;
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
