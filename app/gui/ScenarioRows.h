// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The Simulation dock's scenario rows: which scenario, its parameters
// (simulation Scenario.h), nodes held still from a file and in a box, forces
// on nodes from files, gravity and a floor; what `tetskin simulate` takes as
// its "Scenario" options. A
// parameter the chosen scenario does not read is taken out of the form.

#include <QObject>
#include <string>
#include <vector>

#include "tetskin/session/RunRequest.h"
#include "tetskin/simulation/Scenario.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QWidget;

namespace tetskin::gui {

class ScenarioRows : public QObject {
 public:
  // Appends the rows to `form` (whose other rows share its label column),
  // which must already be in a widget: that widget owns them. `interactive`: false in tests and
  // one-shot screenshots (no file dialogs).
  ScenarioRows(QFormLayout* form, bool interactive);

  std::string scenario() const;
  // Fills `request`'s scenario, its parameters, the held nodes of the file,
  // the loads and their curve read from their files (for a level of
  // `nodeCount` nodes), the held box, gravity and the floor; throws Error
  // naming the file and line.
  void fill(Index nodeCount, RunRequest& request) const;
  // Shows `request`'s scenario, its numbers, the held box, gravity and the
  // floor (a scene's run); the file rows are emptied, since fill keeps what
  // the request holds where they are empty.
  void show(const RunRequest& request);
  // The dataset's up axis: the floor's height is along it, and gravity
  // left at the standard pull down the last axis follows it.
  void setUpAxis(UpAxis up);
  // The floor's height offered until the user sets one: the body's lowest
  // point at rest, along the up axis.
  void setBodyBottom(double height);
  // The fixed box offered until the user holds nodes in one: the level's
  // extent at rest, to narrow to a beam's end, say.
  void setBodyBox(const BoundingBox& box);

 private:
  void showRowsOfScenario();
  // Whether the gravity fields hold the standard pull down the up axis.
  bool standardGravity() const;

  struct ParameterRow {
    QLabel* label;
    QWidget* field;
    ScenarioParameter parameter;
  };

  QFormLayout* form_;
  int scenarioRow_;  // the form's row of the scenario box
  QComboBox* scenario_;
  QDoubleSpinBox *baseShare_, *push_, *pushFrequency_, *dropHeight_, *twistDegrees_, *twistSeconds_,
      *gravity_[3], *floorHeight_, *loadSeconds_;
  QLineEdit* fixedNodes_;  // a node list file (io NodeList.h), or empty
  QLineEdit* loads_;       // a node forces file (io NodeList.h), or empty
  QLineEdit* loadCurve_;   // a load curve file (io LoadCurveFile.h), or empty
  QCheckBox* floor_;
  QCheckBox* fixedBox_;  // hold the nodes in the box below
  QDoubleSpinBox *boxMin_[3], *boxMax_[3];
  UpAxis up_ = UpAxis::Y;
  // The rows of the parameters only some scenarios read, in form order.
  std::vector<ParameterRow> parameterRows_;
};

}  // namespace tetskin::gui
