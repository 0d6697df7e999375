// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The comparison of two levels in the GUI: the Simulation dock's run on
// both (LevelComparison, modules/session), stepped with a progress dialog
// the user may cancel, its frames kept for the Compare dock to show and
// step through. The window only forwards to it (MainWindow.h).

#include <QObject>

#include "Scene.h"
#include "WindowServices.h"

namespace tetskin::gui {

class CompareDock;
class SimulationDock;

class ComparisonController : public QObject {
  Q_OBJECT
 public:
  // Answers `compareDock`'s Compare button with `simulationDock`'s run.
  ComparisonController(Scene& scene, SimulationDock& simulationDock, CompareDock& compareDock,
                       WindowServices& window);

  // Runs the Simulation dock's scenario on `inspected` and `reference` for
  // `steps` steps and shows the result in the Compare dock. False on error
  // (reported to the window), or when cancelled.
  bool compareLevels(int reference, int inspected, int steps);

 private:
  Scene& scene_;
  SimulationDock& simulationDock_;
  CompareDock& compareDock_;
  WindowServices& window_;
};

}  // namespace tetskin::gui
