// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Simulation dock's Recorded run box: a run (.pvd from Record or
// `tetskin simulate`) of the simulated level, opened to step through with a
// frame slider, Play (the frames at their recorded times), Film... (into a
// movie, as the view shows it), Continue from here and Close. It reads and checks the frames;
// MainWindow shows them and owns the simulation.

#include <QGroupBox>
#include <QString>
#include <filesystem>
#include <optional>
#include <string>

#include "tetskin/core/TetMesh.h"
#include "tetskin/vtkio/RecordedRun.h"

class QLabel;
class QPushButton;
class QSlider;
class QTimer;

namespace tetskin::gui {

class RecordedRunPanel : public QGroupBox {
  Q_OBJECT
 public:
  explicit RecordedRunPanel(QWidget* parent = nullptr);

  // Opens the run `pvd` of level `level` of the dataset `dataset`, whose
  // rest mesh is `rest`, at its first frame (not yet shown: frameChosen is
  // not emitted). Throws Error naming the file, and stays as it was, for a
  // run RecordedRun refuses, frames of another level, or a first frame of
  // another body.
  void open(const std::filesystem::path& pvd, const std::filesystem::path& dataset, int level,
            TetMesh rest);
  bool isOpen() const { return run_.has_value(); }
  void close();
  // Stops Play (the simulation's state is to be shown).
  void pause();
  // Whether the open run is of another dataset or level than these.
  bool isOfAnotherLevel(const std::filesystem::path& dataset, int level) const;
  std::size_t frameCount() const { return run_ ? run_->frameCount() : 0; }
  int frame() const;
  // Chooses frame `frame` without frameChosen (the caller shows it).
  void setFrame(int frame);
  // The mean time between the frames (a film's rate); 0 when not open.
  double meanFrameSeconds() const { return run_ ? run_->meanFrameSeconds() : 0; }
  // The run's floor and prescribed nodes (RecordedRun); none when not open.
  RunConditions conditions() const {
    return run_ ? RunConditions{run_->floor(), run_->prescribedNodes()} : RunConditions{};
  }
  // The file of the frame chosen (body 0's for a run of several bodies),
  // its state (the bodies' union; throws Error naming the file, as
  // readSimulationFrame) and its name in messages ("frame 7 of RUN.pvd").
  // All only while open.
  const std::string& frameFile() const;
  FrameState state() const;
  std::string frameName() const;
  // Whether the open run is of several bodies (a frame per body).
  bool ofSeveralBodies() const { return run_ && run_->bodyCount() > 1; }

 Q_SIGNALS:
  // The slider chose another frame.
  void frameChosen(int frame);
  // Continue: the simulation to start from the frame chosen (state()).
  void continueRequested();
  // Film...: the run into a movie, as the view shows it.
  void filmRequested();
  void closeRequested();

 private:
  std::optional<RecordedRun> run_;
  std::filesystem::path dataset_;
  int level_ = -1;
  TetMesh rest_;
  std::string restName_;  // names rest_ in messages
  QSlider* slider_;
  QLabel* label_;
  QPushButton* play_;
  QTimer* timer_;  // plays the frames at their recorded times

  void showFrameText();
  // While playing: the next frame after its recorded time step, or the end.
  void scheduleNextFrame();
};

}  // namespace tetskin::gui
