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
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QProgressDialog>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <cmath>

#include "BuildDialog.h"
#include "EnergyPlot.h"
#include "RecordedRunPanel.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/session/LevelComparison.h"
#include "tetskin/session/SkinFields.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::gui {
namespace {

constexpr int kMaxRecent = 8;

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
  viewDock_ = new ViewDock(*scene_);
  simulationDock_ = new SimulationDock(*scene_, interactive_);
  bindingDock_ = new BindingDock(*scene_);
  compareDock_ = new CompareDock(*scene_);
  runPanel_ = simulationDock_->runPanel();
  energyPlot_ = simulationDock_->energyPlot();
  QDockWidget* viewDock = dock("View", viewDock_);
  QDockWidget* simulationDock = dock("Simulation", simulationDock_);
  QDockWidget* bindingDock = dock("Binding", bindingDock_);
  QDockWidget* compareDock = dock("Compare", compareDock_);
  tabifyDockWidget(viewDock, simulationDock);
  tabifyDockWidget(bindingDock, compareDock);
  viewDock->raise();
  bindingDock->raise();
  connectDocks();
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

void MainWindow::connectDocks() {
  auto redraw = [this] { renderNow(); };
  auto failed = [this](const QString& message) { fail(message); };
  connect(viewDock_, &ViewDock::redraw, this, redraw);
  connect(viewDock_, &ViewDock::failed, this, failed);
  connect(viewDock_, &ViewDock::renderPathChosen, this,
          [this](const QString& name) { setRenderPath(name); });
  connect(viewDock_, &ViewDock::upAxisChanged, this, [this] {
    resetSimulation();
    renderNow();
  });
  connect(bindingDock_, &BindingDock::redraw, this, redraw);
  connect(compareDock_, &CompareDock::redraw, this, redraw);
  connect(compareDock_, &CompareDock::compareRequested, this, [this] {
    compareLevels(compareDock_->referenceLevel(), compareDock_->inspectedLevel(),
                  compareDock_->steps());
  });
  connect(bindingDock_, &BindingDock::rebindRequested, this,
          [this](BindingMethod method, int level) {
            try {
              scene_->rebind(method, level);
              closeRunIfItNoLongerFits();
              viewDock_->setControlLevel(scene_->level());
              resetSimulation();
              bindingDock_->refresh();
              renderNow();
            } catch (const std::exception& e) {
              fail(e.what());
            }
          });
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
  connect(simulationDock_, &SimulationDock::playToggled, this, [this](bool on) {
    if (!runner_) return;
    if (on) {
      runPanel_->pause();
      replaying_ = false;
      runner_->play();
    } else {
      runner_->pause();
    }
    simulationDock_->showPlaying(on);
  });
  connect(simulationDock_, &SimulationDock::stepRequested, this, [this] {
    if (!runner_) return;
    showPlaying(false);
    runner_->pause();
    runner_->step();
    showLatestState();
    reportSimulationProblems();
  });
  connect(simulationDock_, &SimulationDock::resetRequested, this, [this] { resetSimulation(); });
  connect(simulationDock_, &SimulationDock::fromFrameRequested, this, [this] {
    const QString file = interactive_ ? QFileDialog::getOpenFileName(this, "Start from frame", {},
                                                                     "Simulation frames (*.vtu)")
                                      : "";
    if (!file.isEmpty()) startFromFrame(file);
  });
  connect(simulationDock_, &SimulationDock::recordToggled, this, [this](bool on) {
    if (!on) {
      stopRecording();
      return;
    }
    const QString file =
        interactive_ ? QFileDialog::getSaveFileName(this, "Record run", "run.pvd", "*.pvd") : "";
    if (file.isEmpty() || !startRecording(file)) simulationDock_->showRecording(false);
  });
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
  for (const std::string& name : namesOf<CameraPreset>()) {
    const QString preset = QString::fromStdString(name);
    viewMenu->addAction("Camera: " + preset, this,
                        [this, preset] { viewDock_->chooseCamera(preset); });
  }
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
    simulationDock_->showMaterial(scene_->dataset().config.elasticity);
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
  viewDock_->showDataset();
  bindingDock_->showDataset();
  compareDock_->close();  // (of another dataset or surface)
  compareDock_->showDataset();
  setWindowTitle("TetSkin - " + QString::fromStdString(scene_->datasetPath().filename().string()));
  resetSimulation();
  bindingDock_->refresh();
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
  if (viewDock_->renderPath() != name) {
    viewDock_->chooseRenderPath(name);  // comes back here through the signal
    return;
  }
  try {
    scene_->setRenderPath(fromName<RenderPath>(name.toStdString()));
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    viewDock_->showRenderPath(toString(scene_->renderPath()));
  }
  renderNow();
}

void MainWindow::resetSimulation() {
  stopRecording();  // the new run's time starts again at 0
  runner_.reset();
  scene_->setRunConditions({});  // (the new simulation's, if it starts)
  energyPlot_->clear();
  simulationDock_->clearSupports();
  plottedSteps_ = -1;
  shownSteps_ = -1;
  showPlaying(false);
  if (!scene_->hasDataset()) return;
  SimulationOptions options;
  try {
    const RunSpec spec = simulationDock_->runSpec();
    options = spec.options;
    runner_ = std::make_unique<SimulationRunner>(scene_->dataset().mesh, spec);
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
  if (const QString warnings = takeRunWarnings(); !warnings.isEmpty())
    statusBar()->showMessage(warnings);
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
  if (const QString warnings = takeRunWarnings(); !warnings.isEmpty()) message += "; " + warnings;
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
  showOnSkin(state.vonMisesStress, state.equivalentStrain);  // (none in older frames)
  renderNow();
  return true;
}

void MainWindow::showOnSkin(const Eigen::VectorXd& stress, const Eigen::VectorXd& strain) {
  // (The simulated level is the scene's: its rest mesh is the runner's.)
  if (!scene_->colorsBySimulation() || !scene_->hasSurface() || !runner_) return;
  const bool byStress = scene_->colorBy() == ColorBy::VonMisesStress;
  const Eigen::VectorXd& values = byStress ? stress : strain;
  if (values.size() == 0) return;
  const TetMesh& rest = runner_->simulation().restMesh();
  const Index firstNode =
      scene_->dataset().mesh.levels[static_cast<std::size_t>(scene_->level())].firstNode;
  const std::vector<PointScalars> fields =
      byStress ? skinFields(rest, firstNode, scene_->binding(), values, {})
               : skinFields(rest, firstNode, scene_->binding(), {}, values);
  scene_->setSurfaceScalars(scene_->colorBy(), fields.front().values);
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
  if (scene_->colorsBySimulation()) {
    const FrameFields fields = runner_->simulation().frameFields(state);
    showOnSkin(fields.vonMisesStress, fields.equivalentStrain);
  }
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

bool MainWindow::compareLevels(int reference, int inspected, int steps) {
  if (!scene_->hasDataset() || !scene_->hasSurface()) {
    fail("open a dataset and a surface before comparing levels");
    return false;
  }
  try {
    const MultiLevelTetMesh& mesh = scene_->dataset().mesh;
    const std::vector<RunSpec> specs = {simulationDock_->runSpec(inspected),
                                        simulationDock_->runSpec(reference)};
    LevelComparison comparison(mesh, scene_->surface(), specs, 1, scene_->datasetPath().string());
    ComparedLevels compared;
    compared.reference = reference;
    compared.inspected = inspected;
    compared.diagonal = comparison.diagonal();
    compared.surface = scene_->surface();
    compared.binding = comparison.surface(0).binding;
    const auto keep = [&] {
      const ComparedFrame& frame = comparison.compare();
      compared.times.push_back(frame.time);
      compared.nodes.push_back(datasetPositions(
          mesh, inspected, comparison.session(0)->state().positions, "the compared level"));
      const SurfaceErrors& e = comparison.errors(0);
      compared.distance.emplace_back(e.distance.begin(), e.distance.end());
      compared.angle.emplace_back(e.normalAngle.begin(), e.normalAngle.end());
    };
    std::optional<QProgressDialog> progress;
    if (interactive_) {
      progress.emplace("Comparing level " + QString::number(inspected) + " with level " +
                           QString::number(reference) + "...",
                       "Cancel", 0, steps, this);
      progress->setWindowModality(Qt::WindowModal);
      progress->setMinimumDuration(300);
    }
    keep();
    for (int i = 0; i < steps; ++i) {
      comparison.advance();
      keep();
      if (progress) {
        progress->setValue(i + 1);
        if (progress->wasCanceled()) return false;
      }
    }
    compared.overall = comparison.overall(0);
    compared.inspectedSecondsPerStep = comparison.meanStepSeconds(0);
    compared.referenceSecondsPerStep = comparison.meanStepSeconds(1);
    compareDock_->show(std::move(compared));
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  lastError_.clear();
  if (auto* dock = findChild<QDockWidget*>("CompareDock")) dock->raise();
  statusBar()->showMessage(QString("compared level %1 with level %2 over %3 steps")
                               .arg(inspected)
                               .arg(reference)
                               .arg(steps));
  renderNow();
  return true;
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
  simulationDock_->showSupports(sim.supportReaction(state), sim.fixedNodes().size());
  plottedSteps_ = state.steps;
  lastEnergySample_ = now;
}

void MainWindow::showPlaying(bool playing) {
  simulationDock_->showPlaying(playing);  // (the caller plays or pauses the runner)
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
  if (const QString warnings = takeRunWarnings(); !warnings.isEmpty())
    statusBar()->showMessage(warnings);
}

QString MainWindow::takeRunWarnings() {
  QString text;
  for (const std::string& warning : runner_->session().takeWarnings(OptionNames::Words))
    text += (text.isEmpty() ? "warning: " : "; warning: ") + QString::fromStdString(warning);
  return text;
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

QString MainWindow::vertexInfoText() const {
  return bindingDock_->pickedVertexText();
}

std::optional<Index> MainWindow::clickAt(int x, int y) {
  if (scene_->comparisonShown()) {
    const std::optional<Index> v = scene_->pickComparisonVertex(x, y);
    compareDock_->showVertex(v);
    statusBar()->showMessage(
        v ? QString("vertex %1: its error over time in the Compare dock").arg(*v)
          : "no surface vertex there");
    renderNow();
    return v;
  }
  const std::optional<Index> v = scene_->pickVertex(x, y);
  if (!v) scene_->showPickedVertex(std::nullopt);
  bindingDock_->showPickedVertex();
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
  simulationDock_->showRecording(true);
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
  simulationDock_->showRecording(false);
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
