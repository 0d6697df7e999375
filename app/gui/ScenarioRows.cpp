// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ScenarioRows.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <cmath>

#include "ScientificSpinBox.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/LoadCurveFile.h"
#include "tetskin/io/NodeList.h"

namespace tetskin::gui {

ScenarioRows::ScenarioRows(QFormLayout* form, bool interactive)
    : QObject(form), form_(form), scenarioRow_(form->rowCount()) {
  scenario_ = new QComboBox;
  scenario_->setObjectName("scenario");
  for (const std::string& name : scenarioNames()) scenario_->addItem(QString::fromStdString(name));
  scenario_->setCurrentText(kDefaultScenario);
  using namespace scenario_option;
  baseShare_ = numberBox("baseShare", kBaseShare);
  baseShare_->setSingleStep(0.05);
  baseShare_->setStepType(QAbstractSpinBox::DefaultStepType);
  push_ = numberBox("push", kPushAcceleration);
  pushFrequency_ = numberBox("pushFrequency", kPushFrequency);
  dropHeight_ = numberBox("dropHeight", kDropHeight);
  dropHeight_->setSingleStep(0.1);
  dropHeight_->setStepType(QAbstractSpinBox::DefaultStepType);
  twistDegrees_ = numberBox("twistDegrees", kTwistDegrees);
  twistDegrees_->setSingleStep(15);
  twistDegrees_->setStepType(QAbstractSpinBox::DefaultStepType);
  twistSeconds_ = numberBox("twistSeconds", kTwistSeconds);
  twistSeconds_->setSingleStep(0.1);
  twistSeconds_->setStepType(QAbstractSpinBox::DefaultStepType);

  // A file's name, typed or chosen with "...".
  auto fileRow = [this, interactive](QLineEdit*& edit, const char* name, const ListOption& option,
                                     const char* takes) {
    const QString title = labelOf(option);
    edit = new QLineEdit;
    edit->setObjectName(name);
    edit->setPlaceholderText("none");
    edit->setToolTip(QString(option.help) + ": " + takes);
    auto* choose = new QPushButton("...");
    choose->setObjectName(QString(name) + "Choose");
    auto* row = new QHBoxLayout;
    row->addWidget(edit);
    row->addWidget(choose);
    connect(choose, &QPushButton::clicked, this, [edit, title, interactive] {
      if (!interactive) return;
      const QString file = QFileDialog::getOpenFileName(edit->window(), title, {},
                                                        "Text files (*.txt);;All files (*)");
      if (!file.isEmpty()) edit->setText(file);
    });
    return row;
  };
  QHBoxLayout* fixedRow = fileRow(fixedNodes_, "fixedNodes", kFixedNodes,
                                  "a text file of node numbers, in any scenario");
  QHBoxLayout* loadsRow =
      fileRow(loads_, "loads", kLoads, "a text file of lines NODE FX FY FZ, in any scenario");
  QHBoxLayout* loadCurveRow =
      fileRow(loadCurve_, "loadCurve", kLoadCurve,
              "a text file of lines TIME FACTOR, with a last line 'repeat' to repeat it");

  fixedBox_ = new QCheckBox("hold the nodes inside");
  fixedBox_->setObjectName("fixedBox");
  fixedBox_->setToolTip(QString(kFixedBox.help) + ", in any scenario");
  auto* boxMinRow = new QHBoxLayout;
  auto* boxMaxRow = new QHBoxLayout;
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i) {
    const std::string minName = std::string("fixedBoxMin") + axes[i];
    const std::string maxName = std::string("fixedBoxMax") + axes[i];
    boxMin_[i] = numberBox(minName.c_str(), -kLargest, kLargest, 0, "the box's least coordinate");
    boxMax_[i] =
        numberBox(maxName.c_str(), -kLargest, kLargest, 0, "the box's greatest coordinate");
    boxMin_[i]->setEnabled(false);
    boxMax_[i]->setEnabled(false);
    connect(fixedBox_, &QCheckBox::toggled, boxMin_[i], &QWidget::setEnabled);
    connect(fixedBox_, &QCheckBox::toggled, boxMax_[i], &QWidget::setEnabled);
    boxMinRow->addWidget(boxMin_[i]);
    boxMaxRow->addWidget(boxMax_[i]);
  }

  loadSeconds_ = numberBox("loadSeconds", 0, kLargest, 0, kLoadSeconds.help);
  loadSeconds_->setSpecialValueText("whole run");  // (at 0)

  const SimulationOptions plain;
  auto* gravityRow = new QHBoxLayout;
  const char* gravityNames[3] = {"gravityX", "gravityY", "gravityZ"};
  for (int i = 0; i < 3; ++i) {
    gravity_[i] = numberBox(gravityNames[i], -kLargest, kLargest, plain.gravity[i], kGravity.help);
    gravityRow->addWidget(gravity_[i]);
  }
  floor_ = new QCheckBox("at y =");
  floor_->setObjectName("floor");
  floor_->setToolTip(kFloorHeight.help);
  floorHeight_ = numberBox("floorHeight", -kLargest, kLargest, 0, kFloorHeight.help);
  floorHeight_->setEnabled(false);
  connect(floor_, &QCheckBox::toggled, floorHeight_, &QWidget::setEnabled);
  auto* floorRow = new QHBoxLayout;
  floorRow->addWidget(floor_);
  floorRow->addWidget(floorHeight_, 1);

  form_->addRow("Scenario", scenario_);
  parameterRows_ = {
      {new QLabel(labelOf(kBaseShare)), baseShare_, ScenarioParameter::BaseShare},
      {new QLabel(labelOf(kPushAcceleration)), push_, ScenarioParameter::PushAcceleration},
      {new QLabel(labelOf(kPushFrequency)), pushFrequency_, ScenarioParameter::PushFrequency},
      {new QLabel(labelOf(kDropHeight)), dropHeight_, ScenarioParameter::DropHeight},
      {new QLabel(labelOf(kTwistDegrees)), twistDegrees_, ScenarioParameter::TwistDegrees},
      {new QLabel(labelOf(kTwistSeconds)), twistSeconds_, ScenarioParameter::TwistSeconds}};
  for (const ParameterRow& row : parameterRows_) form_->addRow(row.label, row.field);
  form_->addRow(labelOf(kFixedNodes), fixedRow);
  form_->addRow(labelOf(kFixedBox), fixedBox_);
  form_->addRow("  from (x, y, z)", boxMinRow);
  form_->addRow("  to (x, y, z)", boxMaxRow);
  form_->addRow(labelOf(kLoads), loadsRow);
  form_->addRow(labelOf(kLoadCurve), loadCurveRow);
  form_->addRow(labelOf(kLoadSeconds), loadSeconds_);
  form_->addRow(labelOf(kGravity), gravityRow);
  form_->addRow(labelOf(kFloorHeight), floorRow);
  connect(scenario_, &QComboBox::currentTextChanged, this, [this] { showRowsOfScenario(); });
  showRowsOfScenario();
}

void ScenarioRows::showRowsOfScenario() {
  // Qt 5's QFormLayout keeps the spacing of a hidden row: take the rows out
  // and put back those of this scenario, right below the scenario box.
  for (const ParameterRow& row : parameterRows_) {
    if (form_->indexOf(row.field) >= 0) form_->takeRow(row.field);
    row.label->hide();
    row.field->hide();
  }
  int next = scenarioRow_ + 1;
  for (const ParameterRow& row : parameterRows_)
    if (scenarioReads(scenario(), row.parameter)) {
      form_->insertRow(next++, row.label, row.field);
      row.label->show();
      row.field->show();
    }
}

std::string ScenarioRows::scenario() const {
  return scenario_->currentText().toStdString();
}

void ScenarioRows::fill(Index nodeCount, RunRequest& request) const {
  request.scenario = scenario();
  ScenarioParameters& p = request.parameters;
  p.baseShare = baseShare_->value();
  p.pushAcceleration = push_->value();
  p.pushFrequency = pushFrequency_->value();
  p.dropHeight = dropHeight_->value();
  p.twistDegrees = twistDegrees_->value();
  p.twistSeconds = twistSeconds_->value();
  if (!fixedNodes_->text().isEmpty())
    p.fixedNodes = readNodeList(fixedNodes_->text().toStdString(), nodeCount);
  if (fixedBox_->isChecked()) {
    BoundingBox box;
    for (int i = 0; i < 3; ++i) {
      box.min[i] = boxMin_[i]->value();
      box.max[i] = boxMax_[i]->value();
    }
    request.fixedBox = box;
  }
  if (!loads_->text().isEmpty()) p.loads = readNodeForces(loads_->text().toStdString(), nodeCount);
  if (!loadCurve_->text().isEmpty()) p.loadCurve = readLoadCurve(loadCurve_->text().toStdString());
  if (loadSeconds_->value() > 0) p.loadSeconds = loadSeconds_->value();
  request.up = up_;
  // Gravity as the user left it is the standard pull down the up axis: left
  // to the request's default, as the other front ends leave it.
  if (!standardGravity())
    request.gravity =
        Eigen::Vector3d(gravity_[0]->value(), gravity_[1]->value(), gravity_[2]->value());
  if (floor_->isChecked()) request.floorHeight = floorHeight_->value();
}

void ScenarioRows::show(const RunRequest& request) {
  scenario_->setCurrentText(QString::fromStdString(request.scenario));
  const ScenarioParameters& p = request.parameters;
  baseShare_->setValue(p.baseShare);
  push_->setValue(p.pushAcceleration);
  pushFrequency_->setValue(p.pushFrequency);
  dropHeight_->setValue(p.dropHeight);
  twistDegrees_->setValue(p.twistDegrees);
  twistSeconds_->setValue(p.twistSeconds);
  loadSeconds_->setValue(std::isfinite(p.loadSeconds) ? p.loadSeconds : 0);  // (0: whole run)
  fixedNodes_->clear();
  loads_->clear();
  loadCurve_->clear();
  fixedBox_->setChecked(request.fixedBox.has_value());
  if (request.fixedBox)
    for (int i = 0; i < 3; ++i) {
      boxMin_[i]->setValue(request.fixedBox->min[i]);
      boxMax_[i]->setValue(request.fixedBox->max[i]);
    }
  if (request.up) setUpAxis(*request.up);
  const Eigen::Vector3d pull = request.gravity.value_or(uprightAlong(up_, {}).gravity);
  for (int i = 0; i < 3; ++i) gravity_[i]->setValue(pull[i]);
  floor_->setChecked(request.floorHeight.has_value());
  if (request.floorHeight) floorHeight_->setValue(*request.floorHeight);
}

bool ScenarioRows::standardGravity() const {
  const Eigen::Vector3d standard = uprightAlong(up_, {}).gravity;
  for (int i = 0; i < 3; ++i)
    if (gravity_[i]->value() != standard[i]) return false;
  return true;
}

void ScenarioRows::setUpAxis(UpAxis up) {
  const bool untouched = standardGravity();
  up_ = up;
  if (untouched) {
    const Eigen::Vector3d pull = uprightAlong(up, {}).gravity;
    for (int i = 0; i < 3; ++i) gravity_[i]->setValue(pull[i]);
  }
  floor_->setText(QString("at ") + toString(up) + " =");
}

void ScenarioRows::setBodyBottom(double height) {
  if (!floor_->isChecked()) floorHeight_->setValue(height);
}

void ScenarioRows::setBodyBox(const BoundingBox& box) {
  if (fixedBox_->isChecked()) return;
  for (int i = 0; i < 3; ++i) {
    boxMin_[i]->setValue(box.min[i]);
    boxMax_[i]->setValue(box.max[i]);
  }
}

}  // namespace tetskin::gui
