// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MainWindow.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <QAction>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QStatusBar>
#include <QTimer>
#include <cmath>

#include "BuildDialog.h"
#include "RecentFiles.h"
#include "ViewCapture.h"
#include "ViewMouse.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/session/SceneFile.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::gui {
namespace {

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
  WindowServices& services = *this;  // (a private base: for the controllers only)
  run_ = std::make_unique<RunController>(*scene_, *simulationDock_, services);
  comparison_ =
      std::make_unique<ComparisonController>(*scene_, *simulationDock_, *compareDock_, services);
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
  interactor->SetInteractorStyle(vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New());
  new ViewMouse(view_, interactor, *scene_, *run_, [this](int x, int y) { clickAt(x, y); });
  obstacleBox_ = std::make_unique<ObstacleBox>(
      interactor, [this](std::size_t k, const ObstaclePose& pose) { placeObstacle(k, pose); });

  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, [this] { tick(); });
  timer_->start(16);
  statusBar()->showMessage("Open a dataset (File > Open, or drop files here)");
}

MainWindow::~MainWindow() {
  obstacleBox_.reset();
  run_.reset();  // stop the simulation thread before the scene goes
}

void MainWindow::connectDocks() {
  // (A colouring by the skin's contact needs this frame's.)
  auto redraw = [this] {
    run_->refreshSkinContact();
    renderNow();
  };
  connect(viewDock_, &ViewDock::redraw, this, redraw);
  connect(viewDock_, &ViewDock::failed, this, [this](const QString& message) { fail(message); });
  connect(viewDock_, &ViewDock::renderPathChosen, this,
          [this](const QString& name) { setRenderPath(name); });
  connect(viewDock_, &ViewDock::upAxisChanged, this, [this] {
    run_->reset();
    renderNow();
  });
  connect(bindingDock_, &BindingDock::redraw, this, redraw);
  connect(compareDock_, &CompareDock::redraw, this, redraw);
  connect(bindingDock_, &BindingDock::rebindRequested, this,
          [this](BindingMethod method, int level) {
            try {
              scene_->rebind(method, level);
              run_->closeRunIfItNoLongerFits();
              viewDock_->setControlLevel(scene_->level());
              run_->reset();
              bindingDock_->refresh();
              renderNow();
            } catch (const std::exception& e) {
              fail(e.what());
            }
          });
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction(
      "&Open...", this,
      [this] {
        openFiles(QFileDialog::getOpenFileNames(
            this, "Open", {},
            "TetSkin files (*.json *.node *.ele *.msh *.mesh *.obj *.ply *.stl *.vtp *.vtu "
            "*.pvd);;All files (*)"));
      },
      QKeySequence::Open);
  recent_ = new RecentFiles(file->addMenu("Open &Recent"),
                            [this](const QString& path) { openFile(path); });
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
  obstacleMenu_ = menuBar()->addMenu("&Obstacles");
  obstacleMenu_->setObjectName("obstacleMenu");
  refreshObstacleMenu();
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

void MainWindow::succeed(const QString& message) {
  lastError_.clear();
  if (!message.isEmpty()) statusBar()->showMessage(message);
}

void MainWindow::showStatus(const QString& message) {
  statusBar()->showMessage(message);
}

void MainWindow::raiseDock(const QString& objectName) {
  if (auto* dock = findChild<QDockWidget*>(objectName)) dock->raise();
}

void MainWindow::rememberRecent(const QString& path) {
  recent_->remember(path);
}

QStringList MainWindow::recentFiles() const {
  return recent_->files();
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
    simulationDock_->clearScene();  // (a scene's run, if one was open)
    simulationDock_->showMaterial(scene_->dataset().config.elasticity);
  };
  try {
    if (isSceneFile(path)) {
      openScene(path);
    } else if (isDatasetFile(path)) {
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
                  "is not a file tetskin-gui opens (.json scene or dataset, .node .ele .obj .ply "
                  ".stl .vtp .vtu .pvd)");
    }
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  afterLoad(qpath);
  return true;
}

void MainWindow::openScene(const std::filesystem::path& path) {
  const SceneRun run = loadScene(readScene(path));  // throws before anything changes
  scene_->openScene(run);
  simulationDock_->showScene(
      run.request, run.request.material.over(run.dataset.config.elasticity, OptionNames::Keys));
}

void MainWindow::refreshObstacleMenu() {
  obstacleMenu_->clear();
  obstacleMenu_->addAction("&Add obstacle...", this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, "Add obstacle", {}, "Closed surfaces (*.obj *.ply *.stl *.vtp);;All files (*)");
    if (!path.isEmpty()) addObstacle(path);
  });
  if (scene_->obstacles().empty()) return;
  obstacleMenu_->addSeparator();
  for (std::size_t k = 0; k < scene_->obstacles().size(); ++k) {
    QAction* place = obstacleMenu_->addAction(
        QString("Place %1 with a box").arg(QString::fromStdString(scene_->obstacles()[k].name)));
    place->setCheckable(true);
    place->setChecked(obstacleBox_ && obstacleBox_->shownObstacle() == k);
    connect(place, &QAction::toggled, this, [this, k](bool on) {
      showObstacleBox(on ? std::optional<std::size_t>(k) : std::nullopt);
    });
  }
}

bool MainWindow::addObstacle(const QString& qpath) {
  try {
    if (!scene_->hasDataset()) throw Error("open a dataset or a scene before adding obstacles");
    Obstacle obstacle;
    obstacle.name = qpath.toStdString();
    obstacle.shape = readObstacleShape(qpath.toStdString());
    scene_->addObstacle(std::move(obstacle));
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  refreshObstacleMenu();
  run_->reset();  // (the run meets it from the start)
  succeed("added the obstacle " + qpath + " (Obstacles > Place ... to move it)");
  renderNow();
  return true;
}

bool MainWindow::showObstacleBox(std::optional<std::size_t> k) {
  if (!k) {
    obstacleBox_->hide();
  } else {
    if (*k >= scene_->obstacles().size()) {
      fail(QString("there is no obstacle %1").arg(*k));
      return false;
    }
    run_->pause();  // (placed while paused)
    const Obstacle& o = scene_->obstacles()[*k];
    const double time = run_->runner() ? run_->runner()->state().time : 0.0;
    obstacleBox_->show(*k, boundingBox(o.shape->surface()), o.poseAt(time));
  }
  refreshObstacleMenu();
  renderNow();
  return true;
}

bool MainWindow::placeObstacle(std::size_t k, const ObstaclePose& placement) {
  try {
    scene_->setObstaclePlacement(k, placement);
    run_->pause();
    if (SimulationRunner* runner = run_->runner())
      runner->simulation().setObstaclePlacement(k, placement);
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  run_->refreshSkinContact();
  succeed(QString("placed %1").arg(QString::fromStdString(scene_->obstacles()[k].name)));
  renderNow();
  return true;
}

void MainWindow::afterLoad(const QString& path) {
  lastError_.clear();
  run_->closeRunIfItNoLongerFits();
  rememberRecent(QFileInfo(path).absoluteFilePath());
  viewDock_->showDataset();
  bindingDock_->showDataset();
  compareDock_->close();  // (of another dataset or surface)
  compareDock_->showDataset();
  setWindowTitle("TetSkin - " + QString::fromStdString(scene_->datasetPath().filename().string()));
  obstacleBox_->hide();  // (of the obstacles before)
  refreshObstacleMenu();
  run_->reset();
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

bool MainWindow::openRun(const QString& qpath) {
  if (!scene_->hasDataset()) {
    // A run recorded with its surface names its dataset in the surface's
    // frames: opening the first of them (a binding, taken at its rest
    // shape) brings the dataset and the surface, as a binding does.
    std::string surfaceFrame;
    try {
      const RecordedRun run(qpath.toStdString());
      if (run.bodyCount() > 1)
        throw Error(qpath.toStdString(), 0,
                    "records a scene of " + std::to_string(run.bodyCount()) +
                        " bodies: open the scene first");
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
  return run_->openRun(qpath);
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

void MainWindow::tick() {
  run_->tick();
  if (statistics_.due()) refreshOverlay();
}

void MainWindow::renderNow() {
  const auto start = std::chrono::steady_clock::now();
  window_->Render();
  statistics_.addDraw(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
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
  const SimulationRunner* runner = run_->runner();
  const std::string line =
      statistics_.line(toString(scene_->renderPath()), runner ? runner->lastStepSeconds() : 0.0,
                       runner ? static_cast<long long>(runner->steps()) : 0, run_->lastTimes());
  if (overlayVisible_) scene_->setOverlayText(line);
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
  run_->refreshSkinContact();  // (the picked vertex's contact state)
  bindingDock_->showPickedVertex();
  statusBar()->showMessage(v ? vertexInfoText() : "no surface vertex there");
  renderNow();
  return v;
}

vtkSmartPointer<vtkImageData> MainWindow::grabImage() {
  renderNow();
  return grabViewImage(window_);
}

bool MainWindow::saveScreenshot(const QString& path, bool wholeWindow) {
  try {
    writeScreenshot(path.toStdString(), grabImage(), wholeWindow ? this : nullptr, view_);
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
    if (ext == ".vtu")
      run_->writeControlFrame(path);
    else if (ext == ".vtp")
      writeBinding(path, scene_->deformedBoundSurface());
    else
      throw Error(path.string(), 0, "export as .vtu (control mesh) or .vtp (surface)");
  } catch (const std::exception& e) {
    fail(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage("wrote " + qpath);
  return true;
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
  // A surface dropped beside a skin already shown may be an obstacle
  // for it: the user says which.
  for (const QString& f : files) {
    const std::filesystem::path path = f.toStdString();
    const bool obstacle =
        interactive_ && scene_->hasSurface() && isSurfaceFile(path) && !isSceneFile(path) &&
        QMessageBox::question(this, "TetSkin",
                              "Add " + QFileInfo(f).fileName() +
                                  " as an obstacle? (No: bind it as the skin instead)") ==
            QMessageBox::Yes;
    if (obstacle)
      addObstacle(f);
    else
      openFile(f);
  }
  event->acceptProposedAction();
}

}  // namespace tetskin::gui
