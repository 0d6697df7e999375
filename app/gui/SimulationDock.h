// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Simulation dock: Play, Step, Reset, From frame..., Record; the
// recorded run's box; the energy plot and the supports' reaction; the
// scenario, solver and material the next run is made from (RunSpec). The
// window owns the run (SimulationRunner) and answers the buttons.

#include <QString>
#include <QWidget>
#include <array>
#include <optional>

#include "Scene.h"
#include "tetskin/session/RunRequest.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace tetskin::gui {

class EnergyPlot;
class RecordedRunPanel;
class ScenarioRows;
class SeriesPlot;

class SimulationDock : public QWidget {
  Q_OBJECT
 public:
  // `interactive`: the scenario rows may ask the user (ScenarioRows).
  SimulationDock(Scene& scene, bool interactive, QWidget* parent = nullptr);

  // The run the dock's fields ask for on `level` (the scenario rows set to
  // its body and up axis first), and the run it is (resolveRun): on the
  // scene's level, or another (the Compare dock's levels). Throws Error
  // for a file that cannot be read, or a value the run refuses.
  RunRequest runRequest(int level);
  RunSpec runSpec() { return runSpec(scene_.level()); }
  RunSpec runSpec(int level);
  // A dataset's body in the material fields (what the next Reset uses).
  void showMaterial(const ElasticMaterial& material);
  // A scene's run (SceneRun.h) as the base of the runs the dock asks for:
  // its fields show the scene's values (`material` is its body's), and what
  // the dock has no field for (contact points, the start's velocity, held
  // nodes and loads read from the scene's files, the floor's friction)
  // comes from it, until clearScene (a dataset opened).
  void showScene(const RunRequest& request, const ElasticMaterial& material);
  void clearScene();
  bool showsScene() const { return sceneRequest_.has_value(); }

  RecordedRunPanel* runPanel() const { return runPanel_; }
  EnergyPlot* energyPlot() const { return energyPlot_; }
  // The contacts per step (shown for a run with a floor or obstacles).
  SeriesPlot* contactPlot() const { return contactPlot_; }
  // Play as playing or not, Record as recording or not, without their
  // requests.
  void showPlaying(bool playing);
  void showRecording(bool recording);
  // "Supports: reaction 0,20748.1,0 N on 12 prescribed nodes" (or none).
  void showSupports(const Eigen::Vector3d& reaction, std::size_t prescribed);
  void clearSupports();

 Q_SIGNALS:
  void playToggled(bool on);
  void stepRequested();
  void equilibriumRequested();
  void resetRequested();
  void fromFrameRequested();
  void recordToggled(bool on);

 private:
  Scene& scene_;
  QPushButton *play_, *record_;
  RecordedRunPanel* runPanel_;
  EnergyPlot* energyPlot_;
  SeriesPlot* contactPlot_;
  QLabel* supports_;
  std::optional<RunRequest> sceneRequest_;
  ScenarioRows* scenarioRows_;
  QDoubleSpinBox *timeStep_, *tolerance_;
  std::array<QDoubleSpinBox*, 5> material_;  // materialFields()' order, named by key
  QComboBox *solver_, *tangent_;
};

}  // namespace tetskin::gui
