// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ViewMouse.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>

#include <QMouseEvent>
#include <cmath>

#include "RunController.h"
#include "Scene.h"

namespace tetskin::gui {

ViewMouse::ViewMouse(QVTKOpenGLNativeWidget* view, vtkRenderWindowInteractor* interactor,
                     Scene& scene, RunController& run, std::function<void(int, int)> click)
    : QObject(view),
      view_(view),
      interactor_(interactor),
      scene_(scene),
      run_(run),
      click_(std::move(click)) {
  view_->installEventFilter(this);
  // (Before the camera style's observers: priority 10.)
  interactor->AddObserver(vtkCommand::LeftButtonPressEvent, this, &ViewMouse::onLeftPress, 10.0f);
  interactor->AddObserver(vtkCommand::MouseMoveEvent, this, &ViewMouse::onMouseMove, 10.0f);
  interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, this, &ViewMouse::onLeftRelease,
                          10.0f);
}

bool ViewMouse::onLeftPress(vtkObject*, unsigned long, void*) {
  if (!interactor_->GetShiftKey() || !run_.runner()) return false;
  pullVertex_ =
      scene_.pickVertex(interactor_->GetEventPosition()[0], interactor_->GetEventPosition()[1]);
  return pullVertex_.has_value();  // true: the camera does not move
}

bool ViewMouse::onMouseMove(vtkObject*, unsigned long, void*) {
  if (!pullVertex_) return false;
  run_.pull(*pullVertex_, interactor_->GetEventPosition()[0], interactor_->GetEventPosition()[1]);
  return true;
}

bool ViewMouse::onLeftRelease(vtkObject*, unsigned long, void*) {
  if (!pullVertex_) return false;
  pullVertex_.reset();
  run_.release();
  return true;
}

bool ViewMouse::eventFilter(QObject* watched, QEvent* event) {
  // Clicks are seen here, before VTK: once the camera style has grabbed the
  // interactor's focus on a press, VTK observers no longer see the release.
  if (watched == view_ &&
      (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseButtonRelease)) {
    const auto* mouse = static_cast<QMouseEvent*>(event);
    const double scale = view_->devicePixelRatioF();
    const int x = static_cast<int>(mouse->pos().x() * scale);
    const int y = static_cast<int>((view_->height() - 1 - mouse->pos().y()) * scale);
    if (mouse->button() == Qt::LeftButton && !(mouse->modifiers() & Qt::ShiftModifier)) {
      if (event->type() == QEvent::MouseButtonPress) {
        clickX_ = x;
        clickY_ = y;
      } else if (std::abs(x - clickX_) <= 2 && std::abs(y - clickY_) <= 2) {
        click_(x, y);
      }
    }
  }
  return QObject::eventFilter(watched, event);
}

}  // namespace tetskin::gui
