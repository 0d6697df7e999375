// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The View dock: how the scene is drawn (render path, what is shown, the
// control mesh's style and level, camera, up axis, fur). It sets the scene
// and asks the window to draw; the render path and the up axis, which
// reach beyond the drawing, go to the window as requests.

#include <QString>
#include <QWidget>

#include "Scene.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace tetskin::gui {

class ViewDock : public QWidget {
  Q_OBJECT
 public:
  explicit ViewDock(Scene& scene, QWidget* parent = nullptr);

  // The open dataset's up axis, levels (the control level at the scene's)
  // and fur, without the requests their boxes make when the user changes
  // them.
  void showDataset();
  void setControlLevel(int level);
  QString renderPath() const;
  // Chooses `name` in the box (which requests it, renderPathChosen);
  // showRenderPath only shows it.
  void chooseRenderPath(const QString& name);
  void showRenderPath(const QString& name);
  // A camera preset by name, as if chosen in its box (View > Camera).
  void chooseCamera(const QString& name);
  // The fur as its boxes set it, over the dataset config's.
  FurParameters furParameters() const;

 Q_SIGNALS:
  void redraw();
  void renderPathChosen(const QString& name);
  void upAxisChanged();  // the scene's changed: the simulation starts again
  void failed(const QString& message);

 private:
  Scene& scene_;
  QComboBox *renderPath_, *controlStyle_, *camera_, *upAxis_;
  QSpinBox* controlLevel_;
  QSpinBox* furShells_;
  QDoubleSpinBox* furLength_;
  QComboBox* furLighting_;
  QCheckBox* furFins_;
};

}  // namespace tetskin::gui
