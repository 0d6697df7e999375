// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ObstacleBox.h"

#include <vtkBoxRepresentation.h>
#include <vtkBoxWidget2.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkTransform.h>

#include <Eigen/SVD>
#include <cmath>

#include "tetskin/core/Geometry.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin::gui {

ObstaclePose poseOfBoxTransform(vtkTransform* transform) {
  vtkMatrix4x4* m = transform->GetMatrix();
  Eigen::Matrix3d linear;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) linear(r, c) = m->GetElement(r, c);
  ObstaclePose pose;
  pose.translation = Eigen::Vector3d(m->GetElement(0, 3), m->GetElement(1, 3), m->GetElement(2, 3));
  pose.scale = std::cbrt(std::abs(linear.determinant()));
  // The rotation nearest the linear part (its polar factor).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d rotation = svd.matrixU() * svd.matrixV().transpose();
  if (rotation.determinant() < 0) {  // (a mirrored box: the nearest proper rotation)
    Eigen::Matrix3d u = svd.matrixU();
    u.col(2) *= -1;
    rotation = u * svd.matrixV().transpose();
  }
  pose.rotation = Eigen::Quaterniond(rotation).normalized();
  return pose;
}

namespace {

vtkSmartPointer<vtkTransform> boxTransform(const ObstaclePose& pose) {
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->SetMatrix(toVtkMatrix(pose.affine()));
  return transform;
}

}  // namespace

ObstacleBox::ObstacleBox(vtkRenderWindowInteractor* interactor,
                         std::function<void(std::size_t, const ObstaclePose&)> placed)
    : widget_(vtkSmartPointer<vtkBoxWidget2>::New()), placed_(std::move(placed)) {
  widget_->SetInteractor(interactor);
  widget_->CreateDefaultRepresentation();
  widget_->SetRotationEnabled(true);
  widget_->SetTranslationEnabled(true);
  widget_->SetScalingEnabled(true);
  auto ended = vtkSmartPointer<vtkCallbackCommand>::New();
  ended->SetClientData(this);
  ended->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    static_cast<ObstacleBox*>(self)->finishInteraction();
  });
  widget_->AddObserver(vtkCommand::EndInteractionEvent, ended);
}

ObstacleBox::~ObstacleBox() {
  widget_->Off();
}

void ObstacleBox::show(std::size_t k, const BoundingBox& bounds, const ObstaclePose& pose) {
  auto* representation = vtkBoxRepresentation::SafeDownCast(widget_->GetRepresentation());
  double placed[6] = {bounds.min.x(), bounds.max.x(), bounds.min.y(),
                      bounds.max.y(), bounds.min.z(), bounds.max.z()};
  representation->SetPlaceFactor(1.0);
  representation->PlaceWidget(placed);  // around the obstacle's own bounds
  representation->SetTransform(boxTransform(pose));
  shown_ = k;
  widget_->On();
}

void ObstacleBox::hide() {
  widget_->Off();
  shown_.reset();
}

void ObstacleBox::finishInteraction() {
  if (!shown_) return;
  auto* representation = vtkBoxRepresentation::SafeDownCast(widget_->GetRepresentation());
  auto transform = vtkSmartPointer<vtkTransform>::New();
  representation->GetTransform(transform);
  const ObstaclePose pose = poseOfBoxTransform(transform);
  representation->SetTransform(boxTransform(pose));  // (snapped to a uniform scale)
  placed_(*shown_, pose);
}

}  // namespace tetskin::gui
