// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/FloorActor.h"

#include <vtkActor.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

struct FloorActor::Impl {
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  BoundingBox bounds;
};

FloorActor::FloorActor(const FloorPlane& floor, const BoundingBox& body)
    : impl_(std::make_unique<Impl>()) {
  if (body.empty() || !body.min.allFinite() || !body.max.allFinite())
    throw Error("the floor needs a body to lie under: its box is empty or not finite");
  if (!std::isfinite(floor.height))
    throw Error("the floor height must be finite, got " + formatNumber(floor.height));
  const int up = axisIndex(floor.up);
  const int a = (up + 1) % 3, b = (up + 2) % 3;  // the horizontal axes
  const double side = std::max(body.extent()[a], body.extent()[b]);
  // A body of no width (a point, a line) still gets a floor to be seen on.
  const double half = side > 0 ? 1.5 * side : std::max(1.0, std::abs(floor.height));
  Eigen::Vector3d centre = body.center();
  centre[up] = floor.height;
  Eigen::Vector3d origin = centre, corner1 = centre, corner2 = centre;
  origin[a] -= half;
  origin[b] -= half;
  corner1[a] += half;
  corner1[b] -= half;
  corner2[a] -= half;
  corner2[b] += half;
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(origin.data());
  plane->SetPoint1(corner1.data());
  plane->SetPoint2(corner2.data());
  plane->SetResolution(10, 10);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(plane->GetOutputPort());
  mapper->ScalarVisibilityOff();
  impl_->actor->SetMapper(mapper);
  vtkProperty* p = impl_->actor->GetProperty();
  p->SetColor(0.6, 0.62, 0.64);
  p->SetAmbient(0.3);
  p->SetDiffuse(0.7);
  p->SetSpecular(0);
  p->EdgeVisibilityOn();
  p->SetEdgeColor(0.42, 0.44, 0.47);
  impl_->bounds.extend(origin);
  impl_->bounds.extend(corner1);
  impl_->bounds.extend(corner2);
  impl_->bounds.extend(corner1 + corner2 - origin);
}

FloorActor::~FloorActor() = default;

vtkActor* FloorActor::actor() const {
  return impl_->actor;
}

BoundingBox FloorActor::bounds() const {
  return impl_->bounds;
}

}  // namespace tetskin
