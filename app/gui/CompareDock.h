// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Compare dock: which level is enough (issue #55), in the application.
// Pick a reference level and a level to inspect; Compare runs the
// Simulation dock's scenario on both (LevelComparison, as `tetskin
// compare`), and the dock shows the inspected level's surface coloured by
// its distance from the reference's (or the angle between their normals),
// with a legend, a histogram of the frame's values, a frame slider and
// Play, and the error over time of a vertex clicked in the view. The window
// runs the comparison (it owns the run's settings); the dock keeps its
// frames and draws them through the scene.

#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "Scene.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/session/LevelComparison.h"

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace tetskin::gui {

class HistogramWidget;
class SeriesPlot;

// A comparison of two levels as the dock keeps it: the inspected level's
// binding of the surface and, per frame, the dataset's nodes (to deform it
// again) and each vertex's errors against the reference.
struct ComparedLevels {
  int reference = -1, inspected = -1;
  double diagonal = 0;  // the rest surface's
  double referenceSecondsPerStep = 0, inspectedSecondsPerStep = 0;
  SurfaceMesh surface;     // at rest
  SurfaceBinding binding;  // to the inspected level
  std::vector<double> times;
  std::vector<Points3> nodes;                       // per frame, dataset numbering
  std::vector<std::vector<float>> distance, angle;  // per frame, per vertex (degrees)
  ErrorSpread overall;                              // over every vertex and frame
};

class CompareDock : public QWidget {
  Q_OBJECT
 public:
  CompareDock(Scene& scene, QWidget* parent = nullptr);
  ~CompareDock() override;

  // The levels offered (after a dataset is opened): reference the finest,
  // inspected the coarsest.
  void showDataset();
  int referenceLevel() const;
  int inspectedLevel() const;
  int steps() const;

  // Takes `compared` (from the window's run) and shows its first frame.
  // Throws Error when its binding does not fit the scene's dataset.
  void show(ComparedLevels compared);
  bool hasComparison() const { return compared_.has_value(); }
  const ComparedLevels& compared() const { return *compared_; }
  std::size_t frameCount() const { return compared_ ? compared_->times.size() : 0; }
  int frame() const;
  void setFrame(int frame);
  // What colours the surface: "distance" or "normal angle".
  void setColouring(const QString& name);
  // The vertex whose error over time is plotted; nullopt clears the plot.
  void showVertex(std::optional<Index> vertex);
  std::optional<Index> shownVertex() const { return vertex_; }
  const HistogramWidget* histogram() const { return histogram_; }
  const SeriesPlot* vertexPlot() const { return plot_; }
  // Back to the bound surface (the comparison is dropped).
  void close();

 Q_SIGNALS:
  void compareRequested();
  void redraw();

 private:
  Scene& scene_;
  std::optional<ComparedLevels> compared_;
  std::unique_ptr<SurfaceDeformer> deformer_;
  std::optional<Index> vertex_;
  QSpinBox *reference_, *inspected_, *steps_;
  QComboBox* colouring_;
  QLabel* summary_;
  QLabel* frameText_;
  QSlider* slider_;
  QPushButton *play_, *close_;
  QTimer* timer_;
  HistogramWidget* histogram_;
  SeriesPlot* plot_;

  bool byAngle() const;
  void showFrame();
  void showSummary();
};

}  // namespace tetskin::gui
