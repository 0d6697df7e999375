// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the window's controllers (RunController, ComparisonController) ask
// of the window they work in: to report an error or a result, to draw, to
// grab the view's image, to remember a file. MainWindow implements it; a
// controller holds no widget of the window's own.

#include <vtkSmartPointer.h>

#include <QString>

class QWidget;
class vtkImageData;

namespace tetskin::gui {

class WindowServices {
 public:
  virtual ~WindowServices() = default;
  // An error: the status bar, lastError() and, interactive, a dialog.
  virtual void fail(const QString& message) = 0;
  // Success: `message` in the status bar (none: left as it is), and the
  // last error forgotten.
  virtual void succeed(const QString& message = {}) = 0;
  virtual QString lastError() const = 0;
  // A message that leaves the last error as it is (a warning).
  virtual void showStatus(const QString& message) = 0;
  virtual void renderNow() = 0;
  // The 3D view's image, drawn now.
  virtual vtkSmartPointer<vtkImageData> grabImage() = 0;
  virtual void rememberRecent(const QString& path) = 0;
  // Brings the dock named `objectName` ("SimulationDock") to the front.
  virtual void raiseDock(const QString& objectName) = 0;
  // Whether dialogs may ask the user (false under tests and --screenshot).
  virtual bool interactive() const = 0;
  // The parent of the controllers' dialogs.
  virtual QWidget* dialogParent() = 0;
};

}  // namespace tetskin::gui
