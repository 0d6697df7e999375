// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/ObstacleActor.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSmartPointer.h>

#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {

struct ObstacleActor::Impl {
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  BoundingBox localBounds;
  Eigen::Affine3d toWorld = Eigen::Affine3d::Identity();
};

ObstacleActor::ObstacleActor(const SurfaceMesh& surface) : impl_(std::make_unique<Impl>()) {
  if (surface.triangleCount() == 0) throw Error("an obstacle to draw has no triangles");
  SurfaceMesh drawn = surface;
  drawn.normals.resize(0, 3);  // (VTK's flat shading: the surface is closed, a solid)
  drawn.texcoords.resize(0, 2);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(toVtkPolyData(drawn));
  mapper->ScalarVisibilityOff();
  impl_->actor->SetMapper(mapper);
  vtkProperty* property = impl_->actor->GetProperty();
  property->SetColor(0.55, 0.62, 0.72);
  property->SetOpacity(kOpacity);
  property->SetSpecular(0.2);
  impl_->actor->PickableOff();  // (picking is of the skin's vertices)
  impl_->localBounds = boundingBox(surface.positions);
}

ObstacleActor::~ObstacleActor() = default;

vtkActor* ObstacleActor::actor() const {
  return impl_->actor;
}

void ObstacleActor::setPose(const Eigen::Affine3d& toWorld) {
  impl_->toWorld = toWorld;
  impl_->actor->SetUserMatrix(toVtkMatrix(toWorld));
}

BoundingBox ObstacleActor::bounds() const {
  BoundingBox box;
  const BoundingBox& local = impl_->localBounds;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? local.max.x() : local.min.x(),
                            (corner & 2) ? local.max.y() : local.min.y(),
                            (corner & 4) ? local.max.z() : local.min.z());
    box.extend(impl_->toWorld * p);
  }
  return box;
}

}  // namespace tetskin
