// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// tetskin-gui's window: the VTK view in the middle, docks for the view,
// binding diagnostics, the simulation and the comparison of levels
// (ViewDock, BindingDock, SimulationDock, CompareDock, each its own
// controller over the scene), menus for files and export. The window opens
// files and wires: the run belongs to RunController, the comparison of
// levels to ComparisonController, pictures to ViewCapture.h, File > Open
// Recent to RecentFiles, the mouse in the view to ViewMouse. Every action
// is also a public method, so tests drive the window as a user would
// without dialogs (non-interactive windows report errors through
// lastError()).

#include <vtkSmartPointer.h>

#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <chrono>
#include <memory>
#include <optional>

#include "BindingDock.h"
#include "CompareDock.h"
#include "ComparisonController.h"
#include "FrameStatistics.h"
#include "ObstacleBox.h"
#include "RunController.h"
#include "Scene.h"
#include "SimulationDock.h"
#include "ViewDock.h"
#include "WindowServices.h"

class QMenu;
class QTimer;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkImageData;
class vtkRenderer;

namespace tetskin::gui {

class BuildDialog;
class RecentFiles;

class MainWindow : public QMainWindow, private WindowServices {
  Q_OBJECT
 public:
  explicit MainWindow(bool interactive = true, QWidget* parent = nullptr);
  ~MainWindow() override;

  Scene& scene() { return *scene_; }
  QVTKOpenGLNativeWidget* view() { return view_; }
  vtkRenderer* renderer();
  BuildDialog* buildDialog();
  RunController& run() { return *run_; }
  SimulationRunner* runner() { return run_->runner(); }
  CompareDock* compareDock() { return compareDock_; }
  SimulationDock* simulationDock() { return simulationDock_; }

  // By extension: .json scene (format tetskin-scene: its body, surface,
  // obstacles and run), .json/.node/.ele/.msh/.mesh dataset, .obj/.ply/.stl
  // surface, .vtp binding (with ControlIds) or surface, .vtu simulation
  // frame to start from (startFromFrame), .pvd recorded run (openRun).
  // False on error (see lastError()).
  bool openFile(const QString& path);
  bool openFiles(const QStringList& paths);
  QString lastError() const override { return lastError_; }
  QStringList recentFiles() const;

  void setRenderPath(const QString& name);
  void renderNow() override;
  vtkSmartPointer<vtkImageData> grabImage() override;
  // The 3D view only, or (wholeWindow) the window with its docks.
  bool saveScreenshot(const QString& path, bool wholeWindow = false);
  // .vtu: the simulated level now; .vtp: the deformed bound surface now.
  bool exportFrame(const QString& path);
  // Click (pick), in VTK display coordinates.
  std::optional<Index> clickAt(int x, int y);
  QString vertexInfoText() const;
  // The FPS and timing overlay (off for reproducible screenshots); View >
  // Frame statistics, --no-overlay.
  void setOverlayVisible(bool visible);
  bool overlayVisible() const { return overlayVisible_; }

  // The run's and the comparison's actions (RunController.h,
  // ComparisonController.h). openRun also opens, without a dataset, the
  // dataset and surface the run's surface frames name.
  void resetSimulation() { run_->reset(); }
  bool startFromFrame(const QString& vtu) { return run_->startFromFrame(vtu); }
  bool openRun(const QString& pvd);
  bool showRunFrame() { return run_->showRunFrame(); }
  bool filmRun(const QString& ogv) { return run_->filmRun(ogv); }
  void showLatestState() { run_->showLatestState(); }
  bool startRecording(const QString& pvd) { return run_->startRecording(pvd); }
  void stopRecording() { run_->stopRecording(); }
  Index recordedFrames() const { return run_->recordedFrames(); }
  // Obstacles (Obstacles menu): a closed surface (.obj .ply .stl .vtp) added
  // at its own coordinates, the run started again with it; obstacle k
  // placed (the box widget's end: the next run's, and the paused run's
  // from its next step); the box widget around obstacle k (nullopt: none).
  // False on error.
  bool addObstacle(const QString& path);
  bool placeObstacle(std::size_t k, const ObstaclePose& placement);
  bool showObstacleBox(std::optional<std::size_t> k);
  ObstacleBox& obstacleBox() { return *obstacleBox_; }
  bool compareLevels(int reference, int inspected, int steps) {
    return comparison_->compareLevels(reference, inspected, steps);
  }

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  // WindowServices, for the controllers.
  void fail(const QString& message) override;
  void succeed(const QString& message) override;
  void showStatus(const QString& message) override;
  void rememberRecent(const QString& path) override;
  void raiseDock(const QString& objectName) override;
  bool interactive() const override { return interactive_; }
  QWidget* dialogParent() override { return this; }

  void buildMenus();
  // The docks' requests that reach beyond one dock.
  void connectDocks();
  void afterLoad(const QString& path);
  void openScene(const std::filesystem::path& path);
  // The Obstacles menu's place items, one per obstacle.
  void refreshObstacleMenu();
  void refreshOverlay();
  void tick();

  bool interactive_;
  bool overlayVisible_ = true;
  QVTKOpenGLNativeWidget* view_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  std::unique_ptr<Scene> scene_;
  BuildDialog* buildDialog_ = nullptr;
  RecentFiles* recent_ = nullptr;
  QString lastError_;
  QTimer* timer_;
  ViewDock* viewDock_;
  BindingDock* bindingDock_;
  CompareDock* compareDock_;
  SimulationDock* simulationDock_;
  std::unique_ptr<RunController> run_;
  std::unique_ptr<ComparisonController> comparison_;
  std::unique_ptr<ObstacleBox> obstacleBox_;
  QMenu* obstacleMenu_ = nullptr;
  FrameStatistics statistics_;  // the overlay's
};

}  // namespace tetskin::gui
