// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MainWindow.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "BuildDialog.h"
#include "EnergyPlot.h"
#include "HistogramWidget.h"
#include "RecordedRunPanel.h"
#include "ScientificSpinBox.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::gui {
namespace {

constexpr int kMaxRecent = 8;

QComboBox* combo(const char* name, const QStringList& items) {
  auto* c = new QComboBox;
  c->setObjectName(name);
  c->addItems(items);
  return c;
}

// A combo box offering the names of E's schema (OptionSchema.h), `current`
// chosen, the names' help as its tip.
template <SchemaEnum E>
QComboBox* enumCombo(const char* name, E current) {
  QStringList items;
  for (const std::string& item : namesOf<E>()) items << QString::fromStdString(item);
  QComboBox* c = combo(name, items);
  c->setCurrentText(toString(current));
  c->setToolTip(QString::fromStdString(helpOf<E>()));
  return c;
}

// The value the box names.
template <SchemaEnum E>
E chosen(const QComboBox* box) {
  return fromName<E>(box->currentText().toStdString());
}

// A simulation frame to start from (startFromFrame), not a scene to open.
bool isFrameFile(const std::filesystem::path& path) {
  return lowerExtension(path) == ".vtu";
}

// A recorded run to step through (openRun).
bool isRunFile(const std::filesystem::path& path) {
  return lowerExtension(path) == ".pvd";
}

}  // namespace

MainWindow::MainWindow(bool interactive, QWidget* parent)
    : QMainWindow(parent), interactive_(interactive) {
  setWindowTitle("TetSkin");
  setAcceptDrops(true);
  view_ = new QVTKOpenGLNativeWidget(this);
  view_->setObjectName("view");
  window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  window_->SetMultiSamples(0);
  view_->setRenderWindow(window_);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  window_->AddRenderer(renderer_);
  scene_ = std::make_unique<Scene>(renderer_);
  setCentralWidget(view_);
  view_->installEventFilter(this);

  auto dock = [this](const char* title, QWidget* widget) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(QString(title) + "Dock");
    auto* scroll = new QScrollArea;  // a short window scrolls instead of squeezing
    scroll->setWidget(widget);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    d->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, d);
    return d;
  };
  QDockWidget* viewDock = dock("View", buildViewDock());
  QDockWidget* simulationDock = dock("Simulation", buildSimulationDock());
  dock("Binding", buildBindingDock());
  tabifyDockWidget(viewDock, simulationDock);
  viewDock->raise();
  buildMenus();

  vtkRenderWindowInteractor* interactor = window_->GetInteractor();
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor->SetInteractorStyle(style);
  interactor->AddObserver(vtkCommand::LeftButtonPressEvent, this, &MainWindow::onLeftPress, 10.0f);
  interactor->AddObserver(vtkCommand::MouseMoveEvent, this, &MainWindow::onMouseMove, 10.0f);
  interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, this, &MainWindow::onLeftRelease,
                          10.0f);

  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, [this] { tick(); });
  timer_->start(16);
  overlayStart_ = std::chrono::steady_clock::now();
  statusBar()->showMessage("Open a dataset (File > Open, or drop files here)");
}

MainWindow::~MainWindow() {
  runner_.reset();  // stop the simulation thread before the scene goes
}

QWidget* MainWindow::buildViewDock() {
  auto* w = new QWidget;
  auto* form = new QFormLayout(w);
  renderPath_ = enumCombo("renderPath", RenderPath::Cpu);
  form->addRow("Render path", renderPath_);
  connect(renderPath_, &QComboBox::currentTextChanged, this,
          [this](const QString& name) { setRenderPath(name); });
  showSurface_ = new QCheckBox("surface");
  showSurface_->setObjectName("showSurface");
  showSurface_->setChecked(true);
  form->addRow("Show", showSurface_);
  connect(showSurface_, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setSurfaceVisible(on);
    renderNow();
  });
  auto* showFur = new QCheckBox("fur (fur paths)");
  showFur->setObjectName("showFur");
  showFur->setChecked(true);
  form->addRow("", showFur);
  connect(showFur, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setFurVisible(on);
    renderNow();
  });
  auto* showPrescribed = new QCheckBox("prescribed nodes (held or driven)");
  showPrescribed->setObjectName("showPrescribed");
  showPrescribed->setToolTip(
      "marks the simulated level's nodes that the scenario, the fixed nodes and the fixed box "
      "hold still or drive (a recorded run's while it is shown)");
  form->addRow("", showPrescribed);
  connect(showPrescribed, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setPrescribedNodesShown(on);
    renderNow();
  });
  controlStyle_ = enumCombo("controlStyle", ControlMeshStyle::Wireframe);
  form->addRow("Control mesh", controlStyle_);
  connect(controlStyle_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
    scene_->setControlStyle(fromName<ControlMeshStyle>(name.toStdString()));
    renderNow();
  });
  controlLevel_ = new QSpinBox;
  controlLevel_->setObjectName("controlLevel");
  form->addRow("Control level", controlLevel_);
  connect(controlLevel_, qOverload<int>(&QSpinBox::valueChanged), this, [this](int level) {
    scene_->setControlLevel(level);
    renderNow();
  });
  camera_ = enumCombo("camera", CameraPreset::Iso);
  form->addRow("Camera", camera_);
  connect(camera_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
    scene_->setCamera(fromName<CameraPreset>(name.toStdString()));
    renderNow();
  });
  // The dataset's up axis (its config's, or y): for a z-up model opened
  // as bare .node/.ele, or a config that does not say. The camera and the
  // next run follow it.
  upAxis_ = enumCombo("up", UpAxis::Y);
  upAxis_->setToolTip("the axis that points up: camera presets, scenarios, floor and gravity");
  form->addRow("Up axis", upAxis_);
  connect(upAxis_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
    if (!scene_->hasDataset()) return;
    scene_->setUpAxis(*parseName<UpAxis>(name.toStdString()));
    resetSimulation();
    renderNow();
  });
  furShells_ = new QSpinBox;
  furShells_->setObjectName("furShells");
  furShells_->setRange(1, 256);
  furShells_->setValue(16);
  furLength_ = numberBox("furLength", kLeastPositive, 1, FurParameters{}.length,
                         "fur length / the surface's bounding-box diagonal, in (0, 1]");
  furLighting_ = enumCombo("furLighting", FurParameters{}.lighting);
  furFins_ = new QCheckBox("fins at silhouettes");
  furFins_->setObjectName("furFins");
  form->addRow("Fur shells", furShells_);
  form->addRow("Fur length", furLength_);
  form->addRow("Fur lighting", furLighting_);
  form->addRow("", furFins_);
  auto furChanged = [this] {
    if (!scene_->hasDataset()) return;
    try {
      scene_->setFurParameters(furFromControls());
    } catch (const std::exception& e) {
      fail(e.what());
    }
    renderNow();
  };
  connect(furShells_, qOverload<int>(&QSpinBox::valueChanged), this, furChanged);
  connect(furLength_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, furChanged);
  connect(furLighting_, &QComboBox::currentTextChanged, this, furChanged);
  connect(furFins_, &QCheckBox::toggled, this, furChanged);
  return w;
}

QWidget* MainWindow::buildBindingDock() {
  auto* w = new QWidget;
  auto* layout = new QVBoxLayout(w);
  auto* form = new QFormLayout;
  colorBy_ = enumCombo("colorBy", ColorBy::Material);
  colorBy_->setToolTip("the surface's material, or an array of its binding");
  form->addRow("Colour by", colorBy_);
  connect(colorBy_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
    scene_->setColorBy(static_cast<ColorBy>(index));
    refreshBindingPanel();
    renderNow();
  });
  highlight_ = new QCheckBox("negative weights, far vertices");
  highlight_->setObjectName("highlight");
  form->addRow("Highlight", highlight_);
  connect(highlight_, &QCheckBox::toggled, this, [this](bool on) {
    scene_->setHighlightProblems(on);
    refreshBindingPanel();
    renderNow();
  });
  layout->addLayout(form);
  histogram_ = new HistogramWidget;
  histogram_->setObjectName("histogram");
  layout->addWidget(histogram_);
  vertexInfo_ = new QLabel("Click the surface to inspect a vertex; Shift+drag pulls the body.");
  vertexInfo_->setObjectName("vertexInfo");
  vertexInfo_->setWordWrap(true);
  vertexInfo_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(vertexInfo_);
  auto* rebindRow = new QHBoxLayout;
  rebindMethod_ = enumCombo("rebindMethod", BindingMethod::Closest);
  rebindLevel_ = new QSpinBox;
  rebindLevel_->setObjectName("rebindLevel");
  auto* rebind = new QPushButton("Rebind");
  rebind->setObjectName("rebind");
  rebindRow->addWidget(rebindMethod_);
  rebindRow->addWidget(new QLabel("level"));
  rebindRow->addWidget(rebindLevel_);
  rebindRow->addWidget(rebind);
  layout->addLayout(rebindRow);
  connect(rebind, &QPushButton::clicked, this, [this] {
    try {
      scene_->rebind(chosen<BindingMethod>(rebindMethod_), rebindLevel_->value());
      closeRunIfItNoLongerFits();
      controlLevel_->setValue(scene_->level());
      resetSimulation();
      refreshBindingPanel();
      renderNow();
    } catch (const std::exception& e) {
      fail(e.what());
    }
  });
  comparison_ = new QLabel;
  comparison_->setObjectName("comparison");
  comparison_->setWordWrap(true);
  comparison_->setFont(QFont("monospace", 8));
  layout->addWidget(comparison_);
  layout->addStretch();
  return w;
}

QWidget* MainWindow::buildSimulationDock() {
  auto* w = new QWidget;
  auto* layout = new QVBoxLayout(w);
  auto* buttons = new QHBoxLayout;
  play_ = new QPushButton("Play");
  play_->setObjectName("play");
  play_->setCheckable(true);
  step_ = new QPushButton("Step");
  step_->setObjectName("step");
  reset_ = new QPushButton("Reset");
  reset_->setObjectName("reset");
  fromFrame_ = new QPushButton("From frame...");
  fromFrame_->setObjectName("fromFrame");
  fromFrame_->setToolTip(
      "Reset, then start from the positions and velocities of a frame of this level "
      "(.vtu from Export, Record or tetskin simulate)");
  record_ = new QPushButton("Record");
  record_->setObjectName("record");
  record_->setCheckable(true);
  for (QPushButton* b : {play_, step_, reset_, fromFrame_, record_}) buttons->addWidget(b);
  layout->addLayout(buttons);
  // A recorded run opened to step through (File > Open of its .pvd).
  runPanel_ = new RecordedRunPanel;
  layout->addWidget(runPanel_);
  energyPlot_ = new EnergyPlot;
  energyPlot_->setObjectName("energyPlot");
  layout->addWidget(energyPlot_);
  supports_ = new QLabel;
  supports_->setObjectName("supports");
  supports_->setWordWrap(true);
  supports_->setToolTip(
      "What the held and driven nodes' supports exert on the body in all (a settled body's "
      "weight and loads, opposed); per node in exported and recorded frames (ReactionForce)");
  layout->addWidget(supports_);
  connect(runPanel_, &RecordedRunPanel::frameChosen, this, [this] { showRunFrame(); });
  connect(runPanel_, &RecordedRunPanel::continueRequested, this,
          [this](const QString& frame) { startFromFrame(frame); });
  connect(runPanel_, &RecordedRunPanel::filmRequested, this, [this] {
    const QString file =
        interactive_ ? QFileDialog::getSaveFileName(this, "Film run", "run.ogv", "*.ogv") : "";
    if (!file.isEmpty()) filmRun(file);
  });
  connect(runPanel_, &RecordedRunPanel::closeRequested, this, [this] {
    closeRun();
    showLatestState();
  });
  connect(play_, &QPushButton::toggled, this, [this](bool on) {
    if (!runner_) return;
    if (on) {
      runPanel_->pause();
      replaying_ = false;
      runner_->play();
    } else {
      runner_->pause();
    }
    play_->setText(on ? "Pause" : "Play");
  });
  connect(step_, &QPushButton::clicked, this, [this] {
    if (!runner_) return;
    play_->setChecked(false);
    runner_->step();
    showLatestState();
    reportSimulationProblems();
  });
  connect(reset_, &QPushButton::clicked, this, [this] { resetSimulation(); });
  connect(fromFrame_, &QPushButton::clicked, this, [this] {
    const QString file = interactive_ ? QFileDialog::getOpenFileName(this, "Start from frame", {},
                                                                     "Simulation frames (*.vtu)")
                                      : "";
    if (!file.isEmpty()) startFromFrame(file);
  });
  connect(record_, &QPushButton::toggled, this, [this](bool on) {
    if (!on) {
      stopRecording();
      return;
    }
    const QString file =
        interactive_ ? QFileDialog::getSaveFileName(this, "Record run", "run.pvd", "*.pvd") : "";
    if (file.isEmpty() || !startRecording(file)) record_->setChecked(false);
  });
  auto* form = new QFormLayout;
  // A row too wide for the dock puts its field under its label: the dock
  // fits beside the 3D view of a 1280x800 window without scrolling sideways.
  form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  layout->addLayout(form);  // (first: the rows' widgets then belong to the dock)
  scenarioRows_ = new ScenarioRows(form, interactive_);
  const SimulationOptions defaults;
  solver_ = enumCombo("solver", SolverKind::Automatic);
  tangent_ = enumCombo("tangent", defaults.tangent);
  // The relative residual each solve reaches: a looser one is much cheaper
  // for interactive use (doc/benchmarks.md: the tolerance table).
  tolerance_ = combo("tolerance", {"1e-2", "1e-3", "1e-4", "1e-5", "1e-6", "1e-8"});
  tolerance_->setCurrentText("1e-6");
  tolerance_->setToolTip(QString(simulation_option::kTolerance.help) + " (simulate " +
                         simulation_option::kTolerance.flag + ")");
  // The ranges are those the simulation accepts (CorotatedFem, Simulation).
  timeStep_ = numberBox("timeStep", simulation_option::kTimeStep);
  young_ = numberBox("young", material_option::kYoungsModulus);
  poisson_ = numberBox("poisson", material_option::kPoissonRatio);
  poisson_->setSingleStep(0.01);
  poisson_->setStepType(QAbstractSpinBox::DefaultStepType);
  density_ = numberBox("density", material_option::kDensity);
  massDamping_ = numberBox("massDamping", material_option::kMassDamping);
  stiffnessDamping_ = numberBox("stiffnessDamping", material_option::kStiffnessDamping);
  form->addRow("Solver", solver_);
  form->addRow("Tangent", tangent_);
  form->addRow("Tolerance", tolerance_);
  form->addRow("Time step (s)", timeStep_);
  form->addRow("Young's modulus (Pa)", young_);
  form->addRow("Poisson's ratio", poisson_);
  form->addRow("Density (kg/m^3)", density_);
  form->addRow("Mass damping (1/s)", massDamping_);
  form->addRow("Stiffness damping (s)", stiffnessDamping_);
  layout->addWidget(new QLabel("Changes apply on Reset."));
  layout->addStretch();
  return w;
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction(
      "&Open...", this,
      [this] {
        const QStringList files = QFileDialog::getOpenFileNames(
            this, "Open", {},
            "TetSkin files (*.json *.node *.ele *.msh *.mesh *.obj *.ply "
            "*.stl *.vtp *.vtu *.pvd);;All files "
            "(*)");
        openFiles(files);
      },
      QKeySequence::Open);
  recentMenu_ = file->addMenu("Open &Recent");
  refreshRecentMenu();
  file->addAction("&Build dataset...", this, [this] { buildDialog()->show(); });
  file->addSeparator();
  file->addAction("&Export frame...", this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Export frame", "frame.vtp",
                                                      "Surface (*.vtp);;Control mesh (*.vtu)");
    if (!path.isEmpty()) exportFrame(path);
  });
  file->addAction("&Screenshot...", this, [this] {
    QString path = QFileDialog::getSaveFileName(this, "Screenshot", "tetskin.png", "*.png");
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty())
      path += ".png";  // as the filter says
    if (!path.isEmpty()) saveScreenshot(path);
  });
  file->addSeparator();
  file->addAction("&Quit", this, &QWidget::close, QKeySequence::Quit);
  QMenu* viewMenu = menuBar()->addMenu("&View");
  for (const char* preset : {"iso", "front", "side", "top"})
    viewMenu->addAction(QString("Camera: ") + preset, this,
                        [this, preset] { camera_->setCurrentText(preset); });
  viewMenu->addSeparator();
  // Off for a clean picture (a figure for a paper, a film).
  QAction* overlay = viewMenu->addAction("Frame &statistics");
  overlay->setObjectName("overlayAction");
  overlay->setCheckable(true);
  overlay->setChecked(overlayVisible_);
  connect(overlay, &QAction::toggled, this, [this](bool on) { setOverlayVisible(on); });
}

vtkRenderer* MainWindow::renderer() {
  return renderer_;
}

BuildDialog* MainWindow::buildDialog() {
  if (!buildDialog_) {
    buildDialog_ = new BuildDialog(this);
    connect(buildDialog_, &BuildDialog::built, this,
            [this](const QString& json) { openFile(json); });
  }
  return buildDialog_;
}

void MainWindow::fail(const QString& message) {
  lastError_ = message;
  statusBar()->showMessage("error: " + message);
  if (interactive_) QMessageBox::critical(this, "TetSkin", message);
}

bool MainWindow::openFiles(const QStringList& paths) {
  bool ok = true;
  for (const QString& p : paths) ok = openFile(p) && ok;
  return ok;
}

bool MainWindow::openFile(const QString& qpath) {
  const std::filesystem::path path = qpath.toStdString();
  // The new dataset's body (config section elasticity, or the defaults)
  // replaces what the dock held; a surface opened later keeps the dock's.
  const auto openDataset = [this](const std::filesystem::path& dataset) {
    scene_->openDataset(dataset);
    const ElasticMaterial& material = scene_->dataset().config.elasticity;
    young_->setValue(material.youngsModulus);
    poisson_->setValue(material.poissonRatio);
    density_->setValue(material.density);
    massDamping_->setValue(material.massDamping);
    stiffnessDamping_->setValue(material.stiffnessDamping);
  };
  try {
    if (isDatasetFile(path)) {
      openDataset(path);
    } else if (isSurfaceFile(path)) {
      // A binding (or a frame of one) names its own dataset: opened with it
      // when none is open yet. (The file is read once, checked once a
      // dataset is open.)
      SurfaceOrBinding read = readSurfaceOrBinding(path);
      if (!scene_->hasDataset() && !read.dataset.empty()) {
        if (!std::filesystem::exists(read.dataset))
          throw Error(
              path.string(), 0,
              "names its dataset " + read.dataset + ", which is not there: open its dataset first");
        openDataset(read.dataset);
      }
      scene_->openSurface(path, std::move(read));
    } else if (isFrameFile(path)) {
      return startFromFrame(qpath);  // a state of the open dataset, not a scene to load
    } else if (isRunFile(path)) {
      return openRun(qpath);  // states of the open dataset too
    } else {
      throw Error(path.string(), 0,
                  "is not a file tetskin-gui opens (.json .node .ele .obj .ply .stl .vtp .vtu "
                  ".pvd)");
    }
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  afterLoad(qpath);
  return true;
}

void MainWindow::afterLoad(const QString& path) {
  lastError_.clear();
  closeRunIfItNoLongerFits();
  rememberRecent(QFileInfo(path).absoluteFilePath());
  {
    const QSignalBlocker block(upAxis_);
    upAxis_->setCurrentText(toString(scene_->dataset().config.up));
  }
  const int levels = static_cast<int>(scene_->dataset().mesh.levels.size());
  for (QSpinBox* s : {controlLevel_, rebindLevel_}) {
    const QSignalBlocker block(s);
    s->setRange(0, levels - 1);
    s->setValue(scene_->level());
  }
  {
    const FurParameters& fur = scene_->dataset().config.fur;
    const QSignalBlocker a(furShells_), b(furLength_), c(furLighting_), d(furFins_);
    furShells_->setValue(fur.shells);
    furLength_->setValue(fur.length);
    furLighting_->setCurrentText(toString(fur.lighting));
    furFins_->setChecked(fur.fins);
  }
  setWindowTitle("TetSkin - " + QString::fromStdString(scene_->datasetPath().filename().string()));
  resetSimulation();
  refreshBindingPanel();
  QString message = "opened " + path;
  if (scene_->hasSurface()) {                                                  // as bind warns
    if (const NormalGaps gaps = normalGaps(scene_->surface()); !gaps.empty())  // drawn unlit
      message += "; warning: the surface has " + QString::fromStdString(describe(gaps));
    if (const std::string warning = scene_->misfitWarning(); !warning.empty())
      message += "; warning: " + QString::fromStdString(warning);
  }
  statusBar()->showMessage(message);
  renderNow();
}

void MainWindow::rememberRecent(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value("recentFiles").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecent) recent.removeLast();
  settings.setValue("recentFiles", recent);
  refreshRecentMenu();
}

QStringList MainWindow::recentFiles() const {
  return QSettings().value("recentFiles").toStringList();
}

void MainWindow::refreshRecentMenu() {
  recentMenu_->clear();
  for (const QString& path : recentFiles())
    recentMenu_->addAction(path, this, [this, path] { openFile(path); });
  recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

void MainWindow::setRenderPath(const QString& name) {
  if (renderPath_->currentText() != name) {
    renderPath_->setCurrentText(name);  // comes back here through the signal
    return;
  }
  try {
    scene_->setRenderPath(fromName<RenderPath>(name.toStdString()));
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    const QSignalBlocker block(renderPath_);
    renderPath_->setCurrentText(toString(scene_->renderPath()));
  }
  renderNow();
}

FurParameters MainWindow::furFromControls() const {
  FurParameters fur = scene_->hasDataset() ? scene_->dataset().config.fur : FurParameters{};
  fur.shells = furShells_->value();
  fur.minShells = std::min(fur.minShells, fur.shells);
  fur.length = furLength_->value();
  fur.lighting = chosen<FurLighting>(furLighting_);
  fur.fins = furFins_->isChecked();
  return fur;
}

void MainWindow::resetSimulation() {
  stopRecording();  // the new run's time starts again at 0
  runner_.reset();
  scene_->setRunConditions({});  // (the new simulation's, if it starts)
  energyPlot_->clear();
  supports_->clear();
  plottedSteps_ = -1;
  shownSteps_ = -1;
  shownShortfallSteps_ = 0;
  showPlaying(false);
  if (!scene_->hasDataset()) return;
  const MultiLevelTetMesh& mesh = scene_->dataset().mesh;
  const LevelRange& level = mesh.levels[static_cast<std::size_t>(scene_->level())];
  const UpAxis up = scene_->dataset().config.up;
  scenarioRows_->setUpAxis(up);
  const Points3 restNodes = mesh.nodes.middleRows(level.firstNode, level.nodeCount);
  const BoundingBox restBox = boundingBox(restNodes);
  scenarioRows_->setBodyBottom(restBox.min[axisIndex(up)]);
  scenarioRows_->setBodyBox(restBox);
  SimulationOptions options = scenarioRows_->withGravityAndFloor(SimulationOptions{});
  options.timeStep = timeStep_->value();
  options.material.youngsModulus = young_->value();
  options.material.poissonRatio = poisson_->value();
  options.material.density = density_->value();
  options.material.massDamping = massDamping_->value();
  options.material.stiffnessDamping = stiffnessDamping_->value();
  options.solver = chosen<SolverKind>(solver_);
  options.tolerance = tolerance_->currentText().toDouble();
  options.tangent = chosen<Tangent>(tangent_);
  try {
    RunSpec spec;
    spec.level = scene_->level();
    spec.options = options;
    spec.scenario = scenarioRows_->scenario();
    spec.parameters = scenarioRows_->parameters(restNodes);
    spec.datasetName = scene_->datasetPath().string();
    runner_ = std::make_unique<SimulationRunner>(mesh, spec);
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return;
  }
  if (scene_->deformable()) scene_->deformable()->setFrameSeconds(options.timeStep);
  // Energies below that of a uniform strain of 1e-6 in the body (E V e^2 / 2)
  // are round-off: the plot reads them 0.
  energyPlot_->setNoiseFloor(0.5 * options.material.youngsModulus *
                             std::abs(meshVolume(runner_->simulation().restMesh())) * 1e-12);
  // A drop starts above the rest shape: its ears would start out of view.
  // (A start within the rest shape's box leaves the camera as it is: a
  // surface far from its control mesh is framed alone, as opened.)
  const BoundingBox start = boundingBox(runner_->simulation().state().positions);
  const BoundingBox rest = boundingBox(runner_->simulation().restMesh().nodes);
  if ((start.min.array() < rest.min.array()).any() || (start.max.array() > rest.max.array()).any())
    scene_->keepInView(start);
  if (const std::string warning = nodesBelowFloor(runner_->simulation()); !warning.empty())
    statusBar()->showMessage("warning: " + QString::fromStdString(warning));
  showLatestState();
}

bool MainWindow::startFromFrame(const QString& qpath) {
  if (!runner_) {
    fail("open a dataset before starting from a frame");
    return false;
  }
  FrameState start;
  try {
    start = readSimulationFrame(qpath.toStdString(), runner_->simulation().restMesh(),
                                "level " + std::to_string(scene_->level()) + " of " +
                                    scene_->datasetPath().filename().string());
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  resetSimulation();
  if (!runner_) return false;  // the dock's settings were refused (reported)
  runner_->session().startFrom(start);
  lastError_.clear();
  rememberRecent(QFileInfo(qpath).absoluteFilePath());
  energyPlot_->clear();  // (its start was the scenario's, before the frame's state)
  plottedSteps_ = -1;
  showLatestState();
  QString message = "started from " + qpath;
  if (const std::string warning = nodesBelowFloor(runner_->simulation()); !warning.empty())
    message += "; warning: " + QString::fromStdString(warning);
  statusBar()->showMessage(message);
  return true;
}

bool MainWindow::openRun(const QString& qpath) {
  if (!scene_->hasDataset()) {
    // A run recorded with its surface names its dataset in the surface's
    // frames: opening the first of them (a binding, taken at its rest
    // shape) brings the dataset and the surface, as a binding does.
    std::string surfaceFrame;
    try {
      const RecordedRun run(qpath.toStdString());
      if (!run.surfaceFile())
        throw Error(qpath.toStdString(), 0,
                    "has no surface frames naming its dataset: open the dataset first");
      surfaceFrame = *run.surfaceFile();
    } catch (const std::exception& e) {
      fail(QString::fromStdString(e.what()));
      return false;
    }
    if (!openFile(QString::fromStdString(surfaceFrame))) return false;
  }
  try {
    runPanel_->open(qpath.toStdString(), scene_->datasetPath(), scene_->level(),
                    extractLevel(scene_->dataset().mesh, scene_->level()));
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  lastError_.clear();
  rememberRecent(QFileInfo(qpath).absoluteFilePath());
  if (auto* dock = findChild<QDockWidget*>("SimulationDock")) dock->raise();  // the run's slider
  if (!showRunFrame()) return false;
  statusBar()->showMessage("opened " + qpath + " (" + QString::number(runPanel_->frameCount()) +
                           " frames)");
  return true;
}

bool MainWindow::showRunFrame() {
  if (!runPanel_->isOpen()) return false;
  FrameState state;
  try {
    state = runPanel_->state();
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  if (runner_ && runner_->playing()) {
    runner_->pause();
    showPlaying(false);
  }
  replaying_ = true;
  scene_->setRunConditions(runPanel_->conditions());
  lastTimes_ = scene_->showControlState(state.positions);
  renderNow();
  return true;
}

bool MainWindow::filmRun(const QString& qpath) {
  if (!runPanel_->isOpen()) {
    fail("open a recorded run (.pvd) to film");
    return false;
  }
  const std::filesystem::path path = qpath.toStdString();
  if (lowerExtension(path) != ".ogv") {
    fail(qpath + ": a film is an Ogg Theora movie: the name must end in .ogv");
    return false;
  }
  runPanel_->pause();
  const int shown = runPanel_->frame();
  const int rate = movieRate(runPanel_->meanFrameSeconds());
  const auto frames = static_cast<int>(runPanel_->frameCount());
  std::string error;
  try {
    writeMovieAtomically(path, rate, [&](MovieFile& movie) {
      for (int i = 0; i < frames; ++i) {
        runPanel_->setFrame(i);
        if (!showRunFrame()) throw Error(lastError_.toStdString());  // (already reported)
        movie.add(grabImage());
      }
    });
  } catch (const std::exception& e) {
    error = e.what();
  }
  runPanel_->setFrame(shown);  // the frame shown before, film or not
  showRunFrame();
  if (!error.empty()) {
    fail(QString::fromStdString(error));
    return false;
  }
  statusBar()->showMessage(
      QString("wrote %1 (%2 frames at %3 frames/s)").arg(qpath).arg(frames).arg(rate));
  return true;
}

void MainWindow::closeRunIfItNoLongerFits() {
  if (runPanel_->isOfAnotherLevel(scene_->datasetPath(), scene_->level())) closeRun();
}

void MainWindow::closeRun() {
  runPanel_->close();
  replaying_ = false;
}

void MainWindow::showLatestState() {
  if (!runner_) return;
  runPanel_->pause();
  replaying_ = false;
  scene_->setRunConditions(runner_->simulation().conditions());
  const SimulationState state = runner_->state();
  lastTimes_ = scene_->showControlState(state.positions);
  shownSteps_ = state.steps;
  plotEnergy(state);
  if (runner_->session().recording()) {
    try {
      // The surface as the render path drew it.
      const BoundSurface surface = scene_->deformedBoundSurface();
      runner_->session().recordFrame(state, &surface);
    } catch (const std::exception& e) {
      stopRecording();
      fail(QString::fromStdString(e.what()));
    }
  }
  renderNow();
}

void MainWindow::plotEnergy(const SimulationState& state) {
  // Every step taken by hand; while playing, at most 10 samples a second
  // of wall-clock time (each costs an element pass).
  const auto now = std::chrono::steady_clock::now();
  if (state.steps == plottedSteps_) return;
  if (runner_->playing() && now - lastEnergySample_ < std::chrono::milliseconds(100)) return;
  const Simulation& sim = runner_->simulation();
  const Energies e = sim.energies();
  energyPlot_->add({state.time, e.kinetic, e.elastic, e.gravitational});
  const std::size_t prescribed = sim.fixedNodes().size();
  supports_->setText(prescribed == 0 ? "Supports: none (no node held or driven)"
                                     : QString("Supports: reaction %1 N on %2 prescribed node%3")
                                           .arg(QString::fromStdString(
                                               commaSeparatedToScale(sim.supportReaction(state))))
                                           .arg(prescribed)
                                           .arg(prescribed == 1 ? "" : "s"));
  plottedSteps_ = state.steps;
  lastEnergySample_ = now;
}

void MainWindow::showPlaying(bool playing) {
  if (!play_) return;
  const QSignalBlocker block(play_);  // the caller plays or pauses the runner
  play_->setChecked(playing);
  play_->setText(playing ? "Pause" : "Play");
}

void MainWindow::reportSimulationProblems() {
  if (!runner_) return;
  if (const std::optional<std::string> failure = runner_->takeFailure()) {
    showPlaying(false);  // the runner paused itself
    fail("the simulation paused: " + QString::fromStdString(*failure) + " (Reset starts it again)");
    return;
  }
  // Solves cut off at the iteration limit: in the status bar, as simulate
  // warns, when their count grows.
  Simulation& simulation = runner_->simulation();
  const SolveShortfall shortfall = simulation.solveShortfall();
  if (shortfall.steps == shownShortfallSteps_) return;
  shownShortfallSteps_ = shortfall.steps;
  statusBar()->showMessage(
      "warning: " +
      QString::fromStdString(describe(shortfall, simulation.options(), "the multigrid solver")));
}

void MainWindow::tick() {
  if (runner_ && !replaying_ && runner_->steps() != shownSteps_) showLatestState();
  reportSimulationProblems();
  if (std::chrono::steady_clock::now() - overlayStart_ > std::chrono::milliseconds(500))
    refreshOverlay();
}

void MainWindow::renderNow() {
  const auto start = std::chrono::steady_clock::now();
  window_->Render();
  drawSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++framesSinceOverlay_;
  // A gpu path this OpenGL cannot draw the surface with: say why and draw
  // it on the cpu path instead of showing nothing.
  if (const DeformableSurface* drawing = scene_->deformable())
    if (const std::string problem = drawing->gpuProblem(); !problem.empty()) {
      fail(QString::fromStdString(problem));
      setRenderPath(QString::fromStdString(toString(RenderPath::Cpu)));
    }
}

void MainWindow::setOverlayVisible(bool visible) {
  overlayVisible_ = visible;
  if (auto* action = findChild<QAction*>("overlayAction")) {
    const QSignalBlocker block(action);
    action->setChecked(visible);
  }
  if (!visible) scene_->setOverlayText("");
  renderNow();
}

void MainWindow::refreshOverlay() {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - overlayStart_).count();
  char text[256];
  std::snprintf(text, sizeof text,
                "%s  %.1f fps | step %.1f ms (%lld) | deform %.2f ms | upload %.2f ms | draw "
                "%.1f ms",
                toString(scene_->renderPath()), framesSinceOverlay_ / std::max(seconds, 1e-9),
                runner_ ? 1e3 * runner_->lastStepSeconds() : 0.0,
                static_cast<long long>(runner_ ? runner_->steps() : 0),
                1e3 * lastTimes_.deformSeconds, 1e3 * lastTimes_.uploadSeconds,
                framesSinceOverlay_ ? 1e3 * drawSeconds_ / framesSinceOverlay_ : 0.0);
  if (overlayVisible_) scene_->setOverlayText(text);
  overlayStart_ = now;
  framesSinceOverlay_ = 0;
  drawSeconds_ = 0;
}

void MainWindow::refreshBindingPanel() {
  if (!scene_->hasSurface()) {
    histogram_->setValues({}, "no surface");
    comparison_->clear();
    return;
  }
  const SurfaceBinding& b = scene_->binding();
  const bool distance = scene_->colorBy() == ColorBy::Distance;
  const Eigen::VectorXd& values = distance ? b.distance : b.minBarycentric;
  histogram_->setValues(std::vector<double>(values.data(), values.data() + values.size()),
                        distance ? "Distance" : "MinBarycentric (red: outside)");
  QString comparison = QString::fromStdString(scene_->comparisonText());
  if (scene_->highlightedCount() > 0)
    comparison += QString("\nhighlighted: %1 vertices").arg(scene_->highlightedCount());
  comparison_->setText(QString("%1, level %2\n").arg(toString(b.method)).arg(scene_->level()) +
                       comparison);
  vertexInfo_->setText(vertexInfoText());
}

QString MainWindow::vertexInfoText() const {
  if (!scene_->pickedVertex())
    return "Click the surface to inspect a vertex; Shift+drag pulls the body.";
  const VertexInfo i = scene_->vertexInfo(*scene_->pickedVertex());
  const int n = scene_->binding().controlsPerVertex();
  QString ids, weights;
  for (int k = 0; k < n; ++k) {
    ids += QString::number(i.controlIds[k]) + (k + 1 < n ? " " : "");
    weights += QString::number(i.weights[k], 'f', 4) + (k + 1 < n ? " " : "");
  }
  return QString(
             "vertex %1: element %2, control ids %3, weights %4, distance %5, min barycentric %6")
      .arg(i.vertex)
      .arg(i.face)
      .arg(ids, weights)
      .arg(i.distance, 0, 'g', 4)
      .arg(i.minBarycentric, 0, 'g', 4);
}

std::optional<Index> MainWindow::clickAt(int x, int y) {
  const std::optional<Index> v = scene_->pickVertex(x, y);
  if (!v) scene_->showPickedVertex(std::nullopt);
  vertexInfo_->setText(vertexInfoText());
  statusBar()->showMessage(v ? vertexInfoText() : "no surface vertex there");
  renderNow();
  return v;
}

bool MainWindow::onLeftPress(vtkObject*, unsigned long, void*) {
  vtkRenderWindowInteractor* i = window_->GetInteractor();
  if (!i->GetShiftKey() || !runner_) return false;
  pullVertex_ = scene_->pickVertex(i->GetEventPosition()[0], i->GetEventPosition()[1]);
  pulling_ = pullVertex_.has_value();
  return pulling_;  // true: the camera does not move
}

bool MainWindow::onMouseMove(vtkObject*, unsigned long, void*) {
  if (!pulling_ || !runner_) return false;
  vtkRenderWindowInteractor* i = window_->GetInteractor();
  const VertexInfo info = scene_->vertexInfo(*pullVertex_);
  const Eigen::Vector3d target =
      scene_->displayToWorld(i->GetEventPosition()[0], i->GetEventPosition()[1], info.position);
  // A spring to the mouse, as stiff as the body itself at the scale of its size
  // (the binding summary already holds the surface's bounding-box diagonal).
  const double stiffness =
      0.2 * runner_->simulation().options().material.youngsModulus * scene_->summary().diagonal;
  const LevelRange& r = scene_->dataset().mesh.levels[static_cast<std::size_t>(scene_->level())];
  std::vector<int> nodes;
  Points3 forces(scene_->binding().controlsPerVertex(), 3);
  for (int k = 0; k < scene_->binding().controlsPerVertex(); ++k) {
    nodes.push_back(info.controlIds[k] - static_cast<int>(r.firstNode));
    forces.row(k) = (stiffness * info.weights[k] * (target - info.position)).transpose();
  }
  runner_->pull(nodes, forces);
  if (!runner_->playing()) {
    showPlaying(true);
    runner_->play();
  }
  return true;
}

bool MainWindow::onLeftRelease(vtkObject*, unsigned long, void*) {
  if (!pulling_) return false;
  pulling_ = false;
  runner_->release();
  return true;
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
  // Clicks are seen here, before VTK: once the camera style has grabbed the
  // interactor's focus on a press, VTK observers no longer see the release.
  if (watched == view_ &&
      (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseButtonRelease)) {
    const auto* mouse = static_cast<QMouseEvent*>(event);
    const double scale = view_->devicePixelRatioF();
    const int x = static_cast<int>(mouse->pos().x() * scale);
    const int y = static_cast<int>((view_->height() - 1 - mouse->pos().y()) * scale);
    if (mouse->button() == Qt::LeftButton && !(mouse->modifiers() & Qt::ShiftModifier)) {
      if (event->type() == QEvent::MouseButtonPress) {
        clickX_ = x;
        clickY_ = y;
      } else if (std::abs(x - clickX_) <= 2 && std::abs(y - clickY_) <= 2) {
        clickAt(x, y);
      }
    }
  }
  return QMainWindow::eventFilter(watched, event);
}

vtkSmartPointer<vtkImageData> MainWindow::grabImage() {
  renderNow();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window_);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

QString MainWindow::screenshotNameProblem(const QString& path) {
  // The image is a PNG whatever the name says; a name that says otherwise
  // would mislead whoever opens it.
  if (lowerExtension(path.toStdString()) == ".png") return {};
  return "a screenshot is a PNG image: the name must end in .png";
}

bool MainWindow::saveScreenshot(const QString& path, bool wholeWindow) {
  try {
    if (const QString problem = screenshotNameProblem(path); !problem.isEmpty())
      throw Error(path.toStdString(), 0, problem.toStdString());
    vtkSmartPointer<vtkImageData> view = grabImage();
    if (!wholeWindow) {
      writePng(path.toStdString(), view);
    } else {
      // Qt grabs the widgets but not the OpenGL view (it comes out black
      // under Xvfb): paint VTK's own image of it into place.
      int dims[3];
      view->GetDimensions(dims);
      const int channels = view->GetNumberOfScalarComponents();
      QImage picture(dims[0], dims[1], QImage::Format_RGB888);
      const auto* pixels = static_cast<const unsigned char*>(view->GetScalarPointer());
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
          const unsigned char* p = pixels + channels * (y * dims[0] + x);
          picture.setPixel(x, dims[1] - 1 - y, qRgb(p[0], p[1], p[2]));
        }
      QPixmap window = grab();
      QPainter painter(&window);
      painter.drawImage(QRect(view_->mapTo(this, QPoint(0, 0)), view_->size()), picture);
      painter.end();
      const std::filesystem::path file = path.toStdString();
      writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
        if (!window.save(QString::fromStdString(tmp.string()), "PNG"))
          throw Error(file.string(), 0, "cannot write the PNG image");
      });
    }
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage("wrote " + path);
  return true;
}

bool MainWindow::exportFrame(const QString& qpath) {
  const std::filesystem::path path = qpath.toStdString();
  try {
    const std::string ext = lowerExtension(path);
    if (ext == ".vtu" && replaying_ && runPanel_->isOpen()) {
      // What is shown: the recorded frame, its arrays as the run wrote them.
      writeVtu(path, readVtu(runPanel_->frameFile()));
    } else if (ext == ".vtu") {
      if (!runner_) throw Error("open a dataset first");
      Simulation& sim = runner_->simulation();
      const SimulationState s = runner_->state();
      writeVtu(path, simulationFrame(sim.restMesh(), sim.frameFields(s), scene_->level(),
                                     sim.conditions()));
    } else if (ext == ".vtp") {
      writeBinding(path, scene_->deformedBoundSurface());
    } else {
      throw Error(path.string(), 0, "export as .vtu (control mesh) or .vtp (surface)");
    }
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage("wrote " + qpath);
  return true;
}

bool MainWindow::startRecording(const QString& pvd) {
  if (!scene_->hasSurface() || !runner_) {
    fail("open a dataset and a surface before recording");
    return false;
  }
  try {
    runner_->session().record(pvd.toStdString());
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  showLatestState();  // the first frame
  const QSignalBlocker block(record_);
  record_->setChecked(true);
  return true;
}

Index MainWindow::recordedFrames() const {
  if (!runner_ || !runner_->session().recorder()) return 0;
  return runner_->session().recorder()->frames();
}

void MainWindow::stopRecording() {
  if (!runner_ || !runner_->session().recording()) return;
  const RunRecorder& recorder = *runner_->session().recorder();
  statusBar()->showMessage(QString("recorded %1 frames to %2")
                               .arg(recorder.frames())
                               .arg(QString::fromStdString(recorder.path().string())));
  runner_->session().stopRecording();
  const QSignalBlocker block(record_);
  record_->setChecked(false);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList files;
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile()) files << url.toLocalFile();
  // A dataset first, so that surfaces dropped with it bind to it; frames
  // and runs last, as opening anything else starts the simulation again.
  std::stable_sort(files.begin(), files.end(), [](const QString& a, const QString& b) {
    const auto rank = [](const QString& f) {
      const std::filesystem::path path = f.toStdString();
      return isDatasetFile(path) ? 0 : isFrameFile(path) || isRunFile(path) ? 2 : 1;
    };
    return rank(a) < rank(b);
  });
  openFiles(files);
  event->acceptProposedAction();
}

}  // namespace tetskin::gui
