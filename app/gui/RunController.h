// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The GUI's run: the simulation (a SimulationRunner over the session the
// Simulation dock's request makes), what the dock's buttons ask of it
// (play, step, reset, start from a frame, record), a recorded run stepped
// through and filmed (the dock's Recorded run box), the energy plot's
// samples, the supports' reaction, the user's pull, and the run's warnings
// and failures. The window only forwards to it (MainWindow.h).

#include <Eigen/Core>
#include <QObject>
#include <QString>
#include <chrono>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#include "Scene.h"
#include "WindowServices.h"
#include "tetskin/session/SimulationRunner.h"
#include "tetskin/vtkio/SimulationFrame.h"

namespace tetskin::gui {

class EnergyPlot;
class RecordedRunPanel;
class SimulationDock;

class RunController : public QObject {
  Q_OBJECT
 public:
  // Answers `dock`'s buttons and its Recorded run box.
  RunController(Scene& scene, SimulationDock& dock, WindowServices& window);
  ~RunController() override;

  SimulationRunner* runner() { return runner_.get(); }
  // Whether the open recorded run's frame is shown (not the simulation's).
  bool replaying() const { return replaying_; }
  // What drawing the last state shown cost (the frame statistics).
  const FrameTimes& lastTimes() const { return lastTimes_; }

  // Ends a recording (a series holds one run) and starts the simulation
  // again from the dock's settings (nothing without a dataset).
  void reset();
  // Pauses and moves the run to its static equilibrium (the Simulation
  // dock's Equilibrium), as `simulate --static` does; its iterations and
  // force left in the status bar, or its error (a free body under gravity).
  void solveStatic();
  // Resets, then starts from the positions and velocities of a frame of the
  // simulated level, as `simulate --initial` does; a frame of another level
  // or body is refused with its file and changes nothing.
  bool startFromFrame(const QString& vtu);
  // Resets, then starts from `start` (the state of the simulated level, or
  // of every body of a scene), named `source` in the status bar.
  bool startFrom(const FrameState& start, const QString& source);
  // Opens a run recorded of the simulated level (a dataset is open) at its
  // first frame; one of another level or body is refused with its file.
  bool openRun(const QString& pvd);
  // Shows the open run's chosen frame: the simulation pauses.
  bool showRunFrame();
  // Films the open run (.ogv) as the view shows it, at its recorded rate;
  // the frame shown before is shown again.
  bool filmRun(const QString& ogv);
  // Closes the open run when the dataset or the simulated level changed.
  void closeRunIfItNoLongerFits();
  void closeRun();
  // Draws the latest simulated state (and records it while recording).
  void showLatestState();
  // Pauses a playing simulation (Play shown off), to show a recorded frame
  // or place an obstacle.
  void pause();
  // The skin's contact at the state shown, where the scene wants it (a
  // colouring by it, a picked vertex): after either changes.
  void refreshSkinContact();
  // Writes the simulated level's frame shown now (.vtu): a recorded run's
  // frame as the run wrote it, else the simulation's state. Throws Error.
  void writeControlFrame(const std::filesystem::path& vtu);
  bool startRecording(const QString& pvd);
  void stopRecording();
  Index recordedFrames() const;
  // The timer's beat: shows a state the runner has moved on to, reports its
  // failures and warnings.
  void tick();

  // Pulls surface vertex `vertex` towards the point under display
  // coordinates (x, y) at its depth, with a spring as stiff as the body at
  // its size, playing the run; and lets go.
  void pull(Index vertex, int x, int y);
  void release();

 private:
  void connectDock();
  void showPlaying(bool playing);
  // Adds the simulation's energies at `state` to the plot, and what its
  // supports carry.
  void plotEnergy(const SimulationState& state);
  // A failed step (the runner paused) or more solves at the iteration limit.
  void reportProblems();
  // The run's warnings not shown yet ("warning: ...; warning: ..."), or "".
  QString takeWarnings();
  // The stress or strain (per element of the simulated level; empty: none)
  // on the skin, where the scene is coloured by it.
  void showOnSkin(const Eigen::VectorXd& stress, const Eigen::VectorXd& strain);

  Scene& scene_;
  SimulationDock& dock_;
  WindowServices& window_;
  RecordedRunPanel* runPanel_;  // the dock's
  EnergyPlot* energyPlot_;      // the dock's
  std::unique_ptr<SimulationRunner> runner_;
  bool replaying_ = false;
  Index shownSteps_ = -1;    // the step of the state drawn last
  Index plottedSteps_ = -1;  // the step of the energy plot's last sample
  std::chrono::steady_clock::time_point lastEnergySample_;
  // (time, contacts of the step that ended then), as plotted.
  std::deque<std::pair<double, int>> contactSamples_;
  static constexpr const char* kContactTitle = "contacts per step";
  FrameTimes lastTimes_;
};

}  // namespace tetskin::gui
