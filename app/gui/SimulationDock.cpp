// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SimulationDock.h"

#include <QAbstractSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "EnergyPlot.h"
#include "EnumBox.h"
#include "RecordedRunPanel.h"
#include "ScenarioRows.h"
#include "ScientificSpinBox.h"
#include "SeriesPlot.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/NumberText.h"

namespace tetskin::gui {

SimulationDock::SimulationDock(Scene& scene, bool interactive, QWidget* parent)
    : QWidget(parent), scene_(scene) {
  auto* layout = new QVBoxLayout(this);
  auto* buttons = new QHBoxLayout;
  auto button = [&](const char* text, const char* name) {
    auto* b = new QPushButton(text);
    b->setObjectName(name);
    buttons->addWidget(b);
    return b;
  };
  play_ = button("Play", "play");
  play_->setCheckable(true);
  QPushButton* step = button("Step", "step");
  QPushButton* reset = button("Reset", "reset");
  QPushButton* equilibrium = button("Equilibrium", "equilibrium");
  equilibrium->setToolTip(
      "Pause and move the body to its static equilibrium under the run's loads, gravity, held "
      "nodes, floor and obstacles (Newton's method; the velocities become zero)");
  QPushButton* fromFrame = button("From frame...", "fromFrame");
  fromFrame->setToolTip(
      "Reset, then start from the positions and velocities of a frame of this level "
      "(.vtu from Export, Record or tetskin simulate)");
  record_ = button("Record", "record");
  record_->setCheckable(true);
  layout->addLayout(buttons);
  // A recorded run opened to step through (File > Open of its .pvd).
  runPanel_ = new RecordedRunPanel;
  layout->addWidget(runPanel_);
  energyPlot_ = new EnergyPlot;
  energyPlot_->setObjectName("energyPlot");
  layout->addWidget(energyPlot_);
  contactPlot_ = new SeriesPlot;
  contactPlot_->setObjectName("contactPlot");
  contactPlot_->setToolTip(
      "How many contact points (skin vertices or nodes) touch the floor and the obstacles, per "
      "step");
  contactPlot_->hide();
  layout->addWidget(contactPlot_);
  supports_ = new QLabel;
  supports_->setObjectName("supports");
  supports_->setWordWrap(true);
  supports_->setToolTip(
      "What the held and driven nodes' supports exert on the body in all (a settled body's "
      "weight and loads, opposed); per node in exported and recorded frames (ReactionForce)");
  layout->addWidget(supports_);
  connect(play_, &QPushButton::toggled, this, [this](bool on) { Q_EMIT playToggled(on); });
  connect(step, &QPushButton::clicked, this, [this] { Q_EMIT stepRequested(); });
  connect(reset, &QPushButton::clicked, this, [this] { Q_EMIT resetRequested(); });
  connect(equilibrium, &QPushButton::clicked, this, [this] { Q_EMIT equilibriumRequested(); });
  connect(fromFrame, &QPushButton::clicked, this, [this] { Q_EMIT fromFrameRequested(); });
  connect(record_, &QPushButton::toggled, this, [this](bool on) { Q_EMIT recordToggled(on); });

  auto* form = new QFormLayout;
  // A row too wide for the dock puts its field under its label: the dock
  // fits beside the 3D view of a 1280x800 window without scrolling sideways.
  form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  layout->addLayout(form);  // (first: the rows' widgets then belong to the dock)
  scenarioRows_ = new ScenarioRows(form, interactive);
  const SimulationOptions defaults = defaultRunSettings();
  solver_ = enumCombo("solver", simulation_option::kSolver, defaults.solver);
  tangent_ = enumCombo("tangent", simulation_option::kTangent, defaults.tangent);
  // The ranges, defaults, labels and tips are those of the options' schema
  // (OptionSchema.h). (The relative residual each solve reaches: a looser
  // one is much cheaper for interactive use, doc/benchmarks.md.)
  tolerance_ = numberBox("tolerance", simulation_option::kTolerance);
  timeStep_ = numberBox(simulation_option::kTimeStep.key, simulation_option::kTimeStep);
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    material_[i] = numberBox(fields[i].option->key, *fields[i].option);
    if (fields[i].option == &material_option::kPoissonRatio) {
      // (Poisson's ratio steps by hundredths, not by a share of its value.)
      material_[i]->setSingleStep(0.01);
      material_[i]->setStepType(QAbstractSpinBox::DefaultStepType);
    }
  }
  form->addRow(labelOf(simulation_option::kSolver), solver_);
  form->addRow(labelOf(simulation_option::kTangent), tangent_);
  form->addRow(labelOf(simulation_option::kTolerance), tolerance_);
  form->addRow(labelOf(simulation_option::kTimeStep), timeStep_);
  for (std::size_t i = 0; i < fields.size(); ++i)
    form->addRow(labelOf(*fields[i].option), material_[i]);
  layout->addWidget(new QLabel("Changes apply on Reset."));
  layout->addStretch();
}

RunRequest SimulationDock::runRequest(int levelNumber) {
  const MultiLevelTetMesh& mesh = scene_.dataset().mesh;
  const LevelRange& level = mesh.levels[static_cast<std::size_t>(levelNumber)];
  const UpAxis up = scene_.dataset().config.up;
  scenarioRows_->setUpAxis(up);
  const BoundingBox restBox = boundingBox(mesh.nodes.middleRows(level.firstNode, level.nodeCount));
  scenarioRows_->setBodyBottom(restBox.min[axisIndex(up)]);
  scenarioRows_->setBodyBox(restBox);
  RunRequest request = sceneRequest_.value_or(RunRequest{});
  request.names = OptionNames::Words;
  request.level = levelNumber;
  request.datasetName = scene_.datasetPath().string();
  // (The rows show a scene's gravity, floor and held box: theirs count.)
  request.gravity.reset();
  request.floorHeight.reset();
  request.fixedBox.reset();
  scenarioRows_->fill(level.nodeCount, request);
  request.settings.timeStep = timeStep_->value();
  request.settings.solver = chosen<SolverKind>(solver_);
  request.settings.tolerance = tolerance_->value();
  request.settings.tangent = chosen<Tangent>(tangent_);
  // (The fields show the dataset's material after showMaterial: a value
  // left as shown is the config's.)
  const ElasticMaterial& config = scene_.dataset().config.elasticity;
  request.material = {};  // (a scene's material is in the fields)
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (material_[i]->value() != config.*fields[i].field)
      request.material.set(*fields[i].option, material_[i]->value());
  request.settings.obstacles = scene_.obstacles();  // (as placed and added)
  return request;
}

RunSpec SimulationDock::runSpec(int levelNumber) {
  return resolveRun(runRequest(levelNumber), scene_.dataset().mesh, scene_.dataset().config);
}

void SimulationDock::showMaterial(const ElasticMaterial& material) {
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i) material_[i]->setValue(material.*fields[i].field);
}

void SimulationDock::showScene(const RunRequest& request, const ElasticMaterial& material) {
  sceneRequest_ = request;
  timeStep_->setValue(request.settings.timeStep);
  tolerance_->setValue(request.settings.tolerance);
  solver_->setCurrentText(toString(request.settings.solver));
  tangent_->setCurrentText(toString(request.settings.tangent));
  showMaterial(material);
  scenarioRows_->show(request);
}

void SimulationDock::clearScene() {
  sceneRequest_.reset();
}

void SimulationDock::showPlaying(bool playing) {
  const QSignalBlocker block(play_);  // the caller plays or pauses the runner
  play_->setChecked(playing);
  play_->setText(playing ? "Pause" : "Play");
}

void SimulationDock::showRecording(bool recording) {
  const QSignalBlocker block(record_);
  record_->setChecked(recording);
}

void SimulationDock::showSupports(const Eigen::Vector3d& reaction, std::size_t prescribed) {
  supports_->setText(prescribed == 0
                         ? "Supports: none (no node held or driven)"
                         : QString("Supports: reaction %1 N on %2 prescribed node%3")
                               .arg(QString::fromStdString(commaSeparatedToScale(reaction)))
                               .arg(prescribed)
                               .arg(prescribed == 1 ? "" : "s"));
}

void SimulationDock::clearSupports() {
  supports_->clear();
}

}  // namespace tetskin::gui
