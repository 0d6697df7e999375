// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Binding dock: how well the surface is bound (colouring by a binding
// array, highlighted problems, a histogram, the picked vertex, the summary
// before and after a rebind) and the rebind itself, which the window
// carries out (it reaches the simulation and the recorded run).

#include <QString>
#include <QWidget>

#include "Scene.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace tetskin::gui {

class HistogramWidget;

class BindingDock : public QWidget {
  Q_OBJECT
 public:
  explicit BindingDock(Scene& scene, QWidget* parent = nullptr);

  // The histogram, summary and picked vertex of the scene's binding now.
  void refresh();
  // The picked vertex (or how to pick one) in the panel.
  void showPickedVertex();
  // "vertex 12: element 3, control ids ..., weights ..., distance ...".
  QString pickedVertexText() const;
  // The open dataset's levels, the rebind level at the scene's.
  void showDataset();

 Q_SIGNALS:
  void redraw();
  void rebindRequested(BindingMethod method, int level);

 private:
  Scene& scene_;
  QComboBox *colorBy_, *rebindMethod_;
  QCheckBox* highlight_;
  HistogramWidget* histogram_;
  QLabel *vertexInfo_, *comparison_;
  QSpinBox* rebindLevel_;
};

}  // namespace tetskin::gui
