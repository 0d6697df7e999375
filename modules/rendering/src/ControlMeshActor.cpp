// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/ControlMeshActor.h"

#include <vtkActor.h>
#include <vtkDataSetMapper.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkShrinkFilter.h>
#include <vtkUnstructuredGrid.h>

#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {

struct ControlMeshActor::Impl {
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
};

ControlMeshActor::ControlMeshActor(const TetMesh& rest, ControlMeshStyle style)
    : impl_(std::make_unique<Impl>()) {
  if (style == ControlMeshStyle::None) throw Error("a control mesh actor needs a style to draw");
  impl_->grid = toVtkUnstructuredGrid(rest);
  auto mapper = vtkSmartPointer<vtkDataSetMapper>::New();
  if (style == ControlMeshStyle::ShrunkenTets) {
    auto shrink = vtkSmartPointer<vtkShrinkFilter>::New();
    shrink->SetInputData(impl_->grid);
    shrink->SetShrinkFactor(0.7);
    mapper->SetInputConnection(shrink->GetOutputPort());
  } else {
    mapper->SetInputData(impl_->grid);
  }
  mapper->ScalarVisibilityOff();
  impl_->actor->SetMapper(mapper);
  vtkProperty* p = impl_->actor->GetProperty();
  p->SetColor(0.25, 0.45, 0.8);
  if (style == ControlMeshStyle::Wireframe) {
    p->SetRepresentationToWireframe();
    p->SetLineWidth(1.0);
    p->LightingOff();  // lines have no meaningful normal: lit, they turn black from behind
  } else if (style == ControlMeshStyle::Surface) {
    p->SetOpacity(0.35);
  }
}

ControlMeshActor::~ControlMeshActor() = default;
vtkActor* ControlMeshActor::actor() const {
  return impl_->actor;
}

void ControlMeshActor::update(const ConstPoints3Ref& positions) {
  vtkPoints* points = impl_->grid->GetPoints();
  requireRows("control mesh positions", positions.rows(), points->GetNumberOfPoints(), "nodes");
  for (Index v = 0; v < positions.rows(); ++v)
    points->SetPoint(v, positions(v, 0), positions(v, 1), positions(v, 2));
  points->Modified();
  impl_->grid->Modified();
}

}  // namespace tetskin
