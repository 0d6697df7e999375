// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The mouse in the 3D view beyond the camera's trackball: a click (press
// and release within 2 pixels, no Shift) picks the vertex under it; a
// Shift-drag on the surface pulls the simulated body there (RunController::
// pull), and the camera stays put while it does.

#include <vtkSmartPointer.h>

#include <QObject>
#include <functional>
#include <optional>

#include "tetskin/core/TetMesh.h"

class QVTKOpenGLNativeWidget;
class vtkObject;
class vtkRenderWindowInteractor;

namespace tetskin::gui {

class RunController;
class Scene;

class ViewMouse : public QObject {
  Q_OBJECT
 public:
  // `click` receives a click's VTK display coordinates.
  ViewMouse(QVTKOpenGLNativeWidget* view, vtkRenderWindowInteractor* interactor, Scene& scene,
            RunController& run, std::function<void(int x, int y)> click);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  bool onLeftPress(vtkObject*, unsigned long, void*);
  bool onMouseMove(vtkObject*, unsigned long, void*);
  bool onLeftRelease(vtkObject*, unsigned long, void*);

  QVTKOpenGLNativeWidget* view_;
  vtkRenderWindowInteractor* interactor_;
  Scene& scene_;
  RunController& run_;
  std::function<void(int, int)> click_;
  int clickX_ = -100, clickY_ = -100;
  std::optional<Index> pullVertex_;  // while Shift-dragging
};

}  // namespace tetskin::gui
