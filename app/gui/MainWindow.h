// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// tetskin-gui's window: the VTK view in the middle, docks for the view,
// binding diagnostics, the simulation and the comparison of levels
// (ViewDock, BindingDock, SimulationDock, CompareDock, each its own
// controller over the scene), menus for files
// and export. The window owns the run (SimulationRunner over the session),
// opens files, and answers the docks' requests that reach beyond one dock.
// Every action is also a public method, so tests drive the window as a user
// would without dialogs (non-interactive windows report errors through
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
#include "Scene.h"
#include "SimulationDock.h"
#include "ViewDock.h"
#include "tetskin/session/SimulationRunner.h"
#include "tetskin/vtkio/RunRecorder.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QPushButton;
class QSpinBox;
class QTimer;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkImageData;
class vtkObject;
class vtkRenderer;

namespace tetskin::gui {

class EnergyPlot;
class HistogramWidget;
class RecordedRunPanel;
class BuildDialog;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(bool interactive = true, QWidget* parent = nullptr);
  ~MainWindow() override;

  Scene& scene() { return *scene_; }
  SimulationRunner* runner() { return runner_.get(); }
  QVTKOpenGLNativeWidget* view() { return view_; }
  vtkRenderer* renderer();
  BuildDialog* buildDialog();

  // By extension: .json/.node/.ele dataset, .obj/.ply/.stl surface, .vtp
  // binding (with ControlIds) or surface, .vtu simulation frame to start
  // from (startFromFrame). False on error (see lastError()).
  bool openFile(const QString& path);
  bool openFiles(const QStringList& paths);
  QString lastError() const { return lastError_; }
  QStringList recentFiles() const;

  void setRenderPath(const QString& name);
  void renderNow();
  vtkSmartPointer<vtkImageData> grabImage();
  // The 3D view only, or (wholeWindow) the window with its docks.
  bool saveScreenshot(const QString& path, bool wholeWindow = false);
  // Why `path` cannot name a screenshot (the image is a PNG: the name must
  // end in .png), or an empty string.
  static QString screenshotNameProblem(const QString& path);
  // .vtu: the simulated level now; .vtp: the deformed bound surface now.
  bool exportFrame(const QString& path);
  bool startRecording(const QString& pvd);
  void stopRecording();
  Index recordedFrames() const;
  // Click (pick) and pull, in VTK display coordinates.
  std::optional<Index> clickAt(int x, int y);
  QString vertexInfoText() const;
  // Ends a recording (a series holds one run) and starts the simulation
  // again from the dock's settings.
  void resetSimulation();
  // Resets, then starts from the positions and velocities of a frame of the
  // simulated level (.vtu from Export, Record or `tetskin simulate`), as
  // `simulate --initial` does; a frame of another level or body is refused
  // with its file and changes nothing.
  bool startFromFrame(const QString& vtu);
  // Opens a run recorded of the simulated level (.pvd from Record or
  // `tetskin simulate`) to step through with the Recorded run slider, at its
  // first frame; a run of another level or body is refused with its file
  // and changes nothing. The run stays open while the dataset and the
  // simulated level do (a surface opened or bound afresh is shown under it).
  bool openRun(const QString& pvd);
  // Shows the open run's chosen frame: the simulation pauses, and Play,
  // Step or Reset show it again.
  bool showRunFrame();
  // Films the open run into an Ogg Theora movie (.ogv) as the 3D view shows
  // it (its size, camera, path and diagnostics), at the rate the frames were
  // recorded; written atomically, the frame shown before is shown again.
  bool filmRun(const QString& ogv);
  // Draws the latest simulated state (the timer does this while playing).
  void showLatestState();
  // Compare: runs the Simulation dock's scenario on `inspected` and
  // `reference` for `steps` steps (LevelComparison) and shows the result in
  // the Compare dock. False on error (see lastError()), or when cancelled.
  bool compareLevels(int reference, int inspected, int steps);
  CompareDock* compareDock() { return compareDock_; }
  SimulationDock* simulationDock() { return simulationDock_; }
  // The FPS and timing overlay (off for reproducible screenshots); View >
  // Frame statistics, --no-overlay.
  void setOverlayVisible(bool visible);
  bool overlayVisible() const { return overlayVisible_; }

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void buildMenus();
  // The docks' requests, answered by the window.
  void connectDocks();
  void fail(const QString& message);
  void afterLoad(const QString& path);
  void rememberRecent(const QString& path);
  void refreshRecentMenu();
  void refreshOverlay();
  bool onLeftPress(vtkObject*, unsigned long, void*);
  bool onMouseMove(vtkObject*, unsigned long, void*);
  bool onLeftRelease(vtkObject*, unsigned long, void*);
  void tick();
  // The Play button as playing or not, without telling the runner.
  void showPlaying(bool playing);
  // Adds the simulation's energies at `state` to the energy plot, and shows
  // what its supports carry there.
  void plotEnergy(const SimulationState& state);
  // A step of the runner failed (it paused): the button follows, and the
  // message is shown (lastError()). Or more of its solves stopped at the
  // iteration limit: a warning in the status bar.
  void reportSimulationProblems();
  // The run's warnings not shown yet ("warning: ...; warning: ..."), or "".
  QString takeRunWarnings();
  // The stress or strain of the frame shown (per element of the simulated
  // level; empty: none) on the skin, where the scene is coloured by it.
  void showOnSkin(const Eigen::VectorXd& stress, const Eigen::VectorXd& strain);
  // Closes the open run when the dataset or the simulated level changed.
  void closeRunIfItNoLongerFits();
  void closeRun();

  bool interactive_;
  bool overlayVisible_ = true;
  QVTKOpenGLNativeWidget* view_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<SimulationRunner> runner_;
  BuildDialog* buildDialog_ = nullptr;
  QString lastError_;
  QTimer* timer_;
  QMenu* recentMenu_;
  ViewDock* viewDock_;
  BindingDock* bindingDock_;
  CompareDock* compareDock_;
  SimulationDock* simulationDock_;
  EnergyPlot* energyPlot_;   // the simulation dock's
  Index plottedSteps_ = -1;  // the step of the energy plot's last sample
  std::chrono::steady_clock::time_point lastEnergySample_;
  // The recorded run being stepped through (openRun), and whether its
  // frame is shown rather than the simulation's state.
  RecordedRunPanel* runPanel_;  // the simulation dock's
  bool replaying_ = false;
  // Frame bookkeeping.
  Index shownSteps_ = -1;
  int framesSinceOverlay_ = 0;
  std::chrono::steady_clock::time_point overlayStart_;
  double drawSeconds_ = 0;
  FrameTimes lastTimes_;
  // Mouse.
  int clickX_ = -100, clickY_ = -100;
  bool pulling_ = false;
  std::optional<Index> pullVertex_;
};

}  // namespace tetskin::gui
