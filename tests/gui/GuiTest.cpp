// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: files, view toggles, render paths,
// picking, simulation, pulling, export, recording, the build dialog, drops,
// and a screenshot against its baseline.
#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDropEvent>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QUrl>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

#include "BuildDialog.h"
#include "CompareDock.h"
#include "EnergyPlot.h"
#include "Frames.h"
#include "HistogramWidget.h"
#include "ImageCompare.h"
#include "MainWindow.h"
#include "MovieDecoding.h"
#include "SeriesPlot.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"
#include "vtkTetSkinBufferMapper.h"

namespace tetskin::gui {
namespace {

const QString kData = QString(TETSKIN_SOURCE_DIR) + "/data/";

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(TETSKIN_ACTUAL_DIR) / "scratch";
  std::filesystem::create_directories(dir);
  return dir / name;
}

class Gui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!QApplication::instance()) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    window_ = std::make_unique<MainWindow>(false);
    window_->setOverlayVisible(false);
    window_->view()->setFixedSize(400, 300);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override { window_.reset(); }

  void openSample() {
    ASSERT_TRUE(window_->openFiles({kData + "bunny.json", kData + "bunny.obj"}))
        << window_->lastError().toStdString();
  }
  template <class T>
  T* child(const char* name) {
    T* w = window_->findChild<T*>(name);
    EXPECT_NE(w, nullptr) << name;
    return w;
  }
  double changeFrom(vtkImageData* before) {
    return test::differingPixelShare(before, window_->grabImage());
  }
  // Mouse events as Qt delivers them to the view (QTest's own release does
  // not reach QVTKOpenGLNativeWidget's interactor).
  void mouse(QEvent::Type type, QPoint at, Qt::MouseButtons held,
             Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent event(type, at, window_->view()->mapToGlobal(at), button, held, modifiers);
    QApplication::sendEvent(window_->view(), &event);
  }
  // A click at VTK display coordinates (origin bottom left), through Qt.
  void click(int x, int y) {
    const QPoint at(x, window_->view()->height() - 1 - y);
    mouse(QEvent::MouseButtonPress, at, Qt::LeftButton);
    mouse(QEvent::MouseButtonRelease, at, Qt::NoButton);
  }
  // Display position of a world point.
  Eigen::Vector2d project(const Eigen::Vector3d& p) {
    vtkRenderer* r = window_->renderer();
    r->SetWorldPoint(p.x(), p.y(), p.z(), 1);
    r->WorldToDisplay();
    return {r->GetDisplayPoint()[0], r->GetDisplayPoint()[1]};
  }

  std::unique_ptr<MainWindow> window_;
};

TEST_F(Gui, OpensTheSampleDatasetAndSurface) {
  const auto empty = window_->grabImage();
  openSample();
  const Scene& s = window_->scene();
  EXPECT_EQ(s.dataset().mesh.levels.size(), 3u);
  EXPECT_EQ(s.surface().vertexCount(), 1839);
  EXPECT_EQ(s.level(), 2);  // bound to the finest level
  EXPECT_EQ(s.binding().vertexCount(), 1839);
  EXPECT_TRUE(window_->windowTitle().contains("bunny.json"));
  EXPECT_TRUE(window_->recentFiles().first().endsWith("bunny.obj"))
      << window_->recentFiles().join(", ").toStdString();
  EXPECT_GT(changeFrom(empty), 0.1);  // the bunny is drawn
  EXPECT_EQ(child<QSpinBox>("controlLevel")->maximum(), 2);
}

// A surface with a vertex that has no normal opens, with the warning bind
// gives; the sample's does not warn.
TEST_F(Gui, ASurfaceWithoutNormalsSomewhereOpensWithAWarning) {
  openSample();
  EXPECT_FALSE(window_->statusBar()->currentMessage().contains("warning"))
      << window_->statusBar()->currentMessage().toStdString();
  ASSERT_TRUE(window_->openFile(QString(TETSKIN_SOURCE_DIR) + "/tests/data/zero_area_triangle.obj"))
      << window_->lastError().toStdString();
  EXPECT_TRUE(window_->statusBar()->currentMessage().endsWith(
      "zero_area_triangle.obj; warning: the surface has 1 triangle of zero area (first: triangle "
      "1); 1 vertex without a normal, in no triangle of positive area (first: vertex 3)"))
      << window_->statusBar()->currentMessage().toStdString();
}

// A surface far from the dataset's body binds and opens, with bind's warning
// in the status bar and under the binding's numbers; the sample's has none.
TEST_F(Gui, ASurfaceFarFromTheBodyOpensWithAWarning) {
  openSample();
  EXPECT_FALSE(child<QLabel>("comparison")->text().contains("warning"))
      << child<QLabel>("comparison")->text().toStdString();
  ASSERT_TRUE(window_->openFile(QString(TETSKIN_SOURCE_DIR) + "/tests/data/far_tetrahedron.obj"))
      << window_->lastError().toStdString();
  const QString warning = "warning: a tenth of the vertices lie more than ";
  EXPECT_TRUE(window_->statusBar()->currentMessage().contains("far_tetrahedron.obj; " + warning))
      << window_->statusBar()->currentMessage().toStdString();
  EXPECT_TRUE(child<QLabel>("comparison")
                  ->text()
                  .contains(QRegularExpression("\n" + warning +
                                               "[0-9]+% of level 2's diagonal from its boundary")))
      << child<QLabel>("comparison")->text().toStdString();
}

// Opening a surface frames it (one far from the last would be out of view),
// and opening a surface or dataset keeps the side the camera box names.
TEST_F(Gui, OpeningFramesTheNewSurfaceFromTheChosenSide) {
  openSample();
  child<QComboBox>("camera")->setCurrentText("top");
  vtkCamera* camera = window_->renderer()->GetActiveCamera();
  auto lookingDown = [&] {
    const double* d = camera->GetDirectionOfProjection();
    return std::abs(d[0]) < 1e-9 && std::abs(d[1] + 1) < 1e-9 && std::abs(d[2]) < 1e-9;
  };
  EXPECT_TRUE(lookingDown());
  ASSERT_TRUE(window_->openFile(QString(TETSKIN_SOURCE_DIR) + "/tests/data/far_tetrahedron.obj"))
      << window_->lastError().toStdString();
  const double* focus = camera->GetFocalPoint();
  EXPECT_NEAR(focus[0], 100.5, 1e-9);  // the tetrahedron's box centre
  EXPECT_NEAR(focus[1], 0.5, 1e-9);
  EXPECT_NEAR(focus[2], 0.5, 1e-9);
  EXPECT_TRUE(lookingDown());
  ASSERT_TRUE(window_->openFile(kData + "bunny.json")) << window_->lastError().toStdString();
  EXPECT_TRUE(lookingDown());
  EXPECT_EQ(child<QComboBox>("camera")->currentText(), "top");
}

TEST_F(Gui, BadFilesNameFileAndLineAndChangeNothing) {
  openSample();
  const std::filesystem::path bad = scratch("bad.obj");
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 0 1 nope\nf 1 2 3\n";
  EXPECT_FALSE(window_->openFile(QString::fromStdString(bad.string())));
  EXPECT_TRUE(window_->lastError().contains("bad.obj:3")) << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().surface().vertexCount(), 1839);  // the old surface stays
  const std::filesystem::path badJson = scratch("bad.json");
  std::ofstream(badJson) << "{\n  \"format\": \"tetskin-dataset\",\n  oops\n}\n";
  EXPECT_FALSE(window_->openFile(QString::fromStdString(badJson.string())));
  EXPECT_TRUE(window_->lastError().contains("bad.json:3")) << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().dataset().mesh.levels.size(), 3u);
  EXPECT_FALSE(window_->openFile(QString::fromStdString(scratch("notes.txt").string())));
  EXPECT_TRUE(window_->lastError().contains("is not a file tetskin-gui opens"));
}

TEST_F(Gui, EveryViewToggleChangesThePicture) {
  openSample();
  auto* control = child<QComboBox>("controlStyle");
  control->setCurrentText("none");
  auto previous = window_->grabImage();
  for (const char* style : {"surface", "wireframe", "shrink"}) {
    control->setCurrentText(style);
    ASSERT_NE(window_->scene().controlStyle(), ControlMeshStyle::None);
    const auto image = window_->grabImage();
    EXPECT_GT(test::differingPixelShare(previous, image), 0.005) << style;
    previous = image;
  }
  child<QSpinBox>("controlLevel")->setValue(0);
  EXPECT_EQ(window_->scene().controlLevel(), 0);
  EXPECT_GT(changeFrom(previous), 0.005);  // a coarser wireframe
  control->setCurrentText("none");
  previous = window_->grabImage();
  child<QCheckBox>("showSurface")->setChecked(false);
  EXPECT_GT(changeFrom(previous), 0.1);
  child<QCheckBox>("showSurface")->setChecked(true);
  child<QComboBox>("camera")->setCurrentText("top");
  EXPECT_GT(changeFrom(previous), 0.05);
}

TEST_F(Gui, EveryRenderPathDraws) {
  openSample();
  child<QComboBox>("controlStyle")->setCurrentText("none");
  window_->setRenderPath("cpu");
  const auto cpu = window_->grabImage();
  for (const char* path : {"gpu-1pass", "gpu-2pass", "fur-cpu", "fur-gpu"}) {
    window_->setRenderPath(path);
    EXPECT_TRUE(window_->lastError().isEmpty())
        << path << ": " << window_->lastError().toStdString();
    EXPECT_STREQ(toString(window_->scene().renderPath()), path);
    const double change = changeFrom(cpu);
    if (QString(path).startsWith("fur"))
      EXPECT_GT(change, 0.05) << path;  // fur is there
    else
      EXPECT_LT(change, 0.05) << path;  // the same surface
  }
  child<QCheckBox>("furFins")->setChecked(true);
  EXPECT_TRUE(window_->scene().deformable()->fur()->actors().size() == 2);
  // The fur toggle hides the fur and leaves the skin, also across path changes.
  const auto furry = window_->grabImage();
  child<QCheckBox>("showFur")->setChecked(false);
  EXPECT_GT(changeFrom(furry), 0.05);
  EXPECT_TRUE(window_->scene().surfaceActor()->GetVisibility());
  window_->setRenderPath("gpu-2pass");
  window_->setRenderPath("fur-gpu");
  EXPECT_FALSE(window_->scene().deformable()->fur()->actors()[0]->GetVisibility());
}

// A gpu path that cannot draw the surface on this OpenGL (here: more
// control nodes than the texel limit set on its mapper) says why and
// draws the surface on the cpu path instead of showing nothing.
TEST_F(Gui, AGpuPathTheOpenGLCannotDrawFallsBackToTheCpuPath) {
  openSample();
  child<QComboBox>("controlStyle")->setCurrentText("none");
  window_->setRenderPath("cpu");
  const auto cpu = window_->grabImage();
  window_->setRenderPath("gpu-1pass");
  ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
  Scene& scene = window_->scene();
  vtkTetSkinBufferMapper::SafeDownCast(scene.deformable()->actor()->GetMapper())
      ->SetTexelLimit(100);
  const MultiLevelTetMesh& mesh = scene.dataset().mesh;
  const LevelRange& level = mesh.levels[static_cast<std::size_t>(scene.level())];
  scene.showControlState(mesh.nodes.middleRows(level.firstNode, level.nodeCount));
  window_->renderNow();
  EXPECT_TRUE(window_->lastError().startsWith("gpu-1pass: the positions of "))
      << window_->lastError().toStdString();
  EXPECT_TRUE(window_->lastError().endsWith(": draw it with the cpu path"));
  EXPECT_STREQ(toString(scene.renderPath()), "cpu");
  EXPECT_EQ(child<QComboBox>("renderPath")->currentText(), "cpu");
  EXPECT_LT(changeFrom(cpu), 0.002);
}

TEST_F(Gui, ClickingTheSurfaceReportsTheVertexAndItsControlTriangle) {
  openSample();
  child<QComboBox>("controlStyle")->setCurrentText("none");
  window_->grabImage();
  const int x = window_->view()->width() / 2, y = window_->view()->height() / 2;
  click(x, y);
  const std::optional<Index> picked = window_->scene().pickedVertex();
  ASSERT_TRUE(picked.has_value()) << "nothing picked at the centre of the view: "
                                  << window_->vertexInfoText().toStdString();
  const VertexInfo info = window_->scene().vertexInfo(*picked);
  const SurfaceBinding& b = window_->scene().binding();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(info.controlIds[k], b.controlIds(*picked, k));
    EXPECT_EQ(info.weights[k], b.weights(*picked, k));
  }
  EXPECT_EQ(info.face, b.faceId[*picked]);
  // The vertex is the one under the cursor (within a few pixels at this size).
  const Eigen::Vector2d at = project(info.position);
  EXPECT_LT((at - Eigen::Vector2d(x, y)).norm(), 8.0);
  const QString text = child<QLabel>("vertexInfo")->text();
  EXPECT_TRUE(text.contains(QString("vertex %1:").arg(*picked))) << text.toStdString();
  EXPECT_TRUE(text.contains(QString("control ids %1 %2 %3")
                                .arg(b.controlIds(*picked, 0))
                                .arg(b.controlIds(*picked, 1))
                                .arg(b.controlIds(*picked, 2))))
      << text.toStdString();
  click(2, 2);  // the background: nothing
  EXPECT_FALSE(window_->scene().pickedVertex().has_value());
}

TEST_F(Gui, StepPlayAndResetTheSimulation) {
  openSample();
  ASSERT_NE(window_->runner(), nullptr);
  const Points3 rest = window_->scene().dataset().mesh.nodes;
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->steps(), 3);
  EXPECT_GT((window_->scene().controlNodes() - rest).norm(), 0.0);  // wobble moved it
  QTest::mouseClick(child<QPushButton>("play"), Qt::LeftButton);
  EXPECT_TRUE(window_->runner()->playing());
  EXPECT_TRUE(QTest::qWaitFor([&] { return window_->runner()->steps() >= 6; }, 20000));
  QTest::mouseClick(child<QPushButton>("play"), Qt::LeftButton);
  EXPECT_FALSE(window_->runner()->playing());
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->steps(), 0);
  EXPECT_EQ((window_->scene().controlNodes() - rest).norm(), 0.0);
}

// A step that blows up (a load of 1e40 N) pauses the simulation with the
// simulation's message, whether stepped or playing; the state stays the last
// good one and the window goes on (the exception used to leave the
// runner's thread and end the program). Reset with sane loads runs again.
TEST_F(Gui, ABlownUpStepPausesTheSimulationWithItsMessage) {
  openSample();
  child<QLineEdit>("loads")->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/blowup_loads.txt");
  child<QDoubleSpinBox>("baseShare")->setValue(0);  // node 10 is in the base
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const Points3 rest = window_->runner()->state().positions;
  child<QPushButton>("step")->click();
  EXPECT_TRUE(window_->lastError().startsWith(
      "the simulation paused: the simulation diverged in step 1 (t = 0.0166667 s): node "))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->steps(), 0);
  EXPECT_EQ(window_->runner()->state().positions, rest);
  QPushButton* play = child<QPushButton>("play");
  QTest::mouseClick(play, Qt::LeftButton);
  EXPECT_TRUE(QTest::qWaitFor([&] { return !play->isChecked(); }, 20000));
  EXPECT_EQ(play->text(), "Play");
  EXPECT_FALSE(window_->runner()->playing());
  EXPECT_EQ(window_->runner()->steps(), 0);
  EXPECT_EQ(window_->scene().controlNodes(), window_->scene().dataset().mesh.nodes);
  child<QLineEdit>("loads")->clear();
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  child<QPushButton>("step")->click();
  EXPECT_EQ(window_->runner()->steps(), 1);
}

// A stiff, nearly incompressible body cuts CG's solves off at the
// iteration limit: the status bar says so, as simulate warns; multigrid
// converges there and nothing is said.
TEST_F(Gui, SolvesStoppedAtTheIterationLimitAreWarnedOf) {
  openSample();
  child<QDoubleSpinBox>("young")->setValue(1e13);
  child<QDoubleSpinBox>("poisson")->setValue(0.499);
  child<QComboBox>("solver")->setCurrentText("cg");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  child<QPushButton>("step")->click();
  EXPECT_TRUE(window_->statusBar()->currentMessage().startsWith(
      "warning: 1 step stopped at the iteration limit (2000) with the relative residual above "
      "the tolerance 1e-06 (at most "))
      << window_->statusBar()->currentMessage().toStdString();
  EXPECT_TRUE(window_->statusBar()->currentMessage().endsWith(
      ", in step 1); the multigrid solver needs far fewer iterations on stiff bodies"))
      << window_->statusBar()->currentMessage().toStdString();
  child<QComboBox>("solver")->setCurrentText("multigrid");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  window_->statusBar()->clearMessage();
  child<QPushButton>("step")->click();
  EXPECT_EQ(window_->runner()->simulation().solveShortfall().steps, 0);
  EXPECT_EQ(window_->statusBar()->currentMessage(), "");
}

// The Simulation dock starts from the dataset's elasticity section (the
// defaults where it has no value); the simulation takes the dock's material;
// a surface opened afterwards leaves the dock as the user set it.
TEST_F(Gui, SimulationTakesTheDatasetsMaterial) {
  const QString stiff = QString(TETSKIN_SOURCE_DIR) + "/tests/data/stiff_bunny.json";
  ASSERT_TRUE(window_->openFiles({stiff})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("young")->value(), 2e6);
  EXPECT_EQ(child<QDoubleSpinBox>("density")->value(), 50.0);
  EXPECT_EQ(child<QDoubleSpinBox>("massDamping")->value(), ElasticMaterial{}.massDamping);
  EXPECT_EQ(child<QDoubleSpinBox>("stiffnessDamping")->value(), ElasticMaterial{}.stiffnessDamping);
  ASSERT_NE(window_->runner(), nullptr);
  auto material = [&] { return window_->runner()->simulation().options().material; };
  EXPECT_EQ(material().youngsModulus, 2e6);
  EXPECT_EQ(material().density, 50.0);
  child<QDoubleSpinBox>("young")->setValue(7e5);
  child<QDoubleSpinBox>("poisson")->setValue(0.4999);
  child<QDoubleSpinBox>("density")->setValue(1200);
  child<QDoubleSpinBox>("massDamping")->setValue(0.5);
  child<QDoubleSpinBox>("stiffnessDamping")->setValue(0.002);
  ASSERT_TRUE(window_->openFiles({kData + "bunny_8k.obj"})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("young")->value(), 7e5);
  EXPECT_EQ(material().youngsModulus, 7e5);
  EXPECT_EQ(material().poissonRatio, 0.4999);
  EXPECT_EQ(material().density, 1200.0);
  EXPECT_EQ(material().massDamping, 0.5);
  EXPECT_EQ(material().stiffnessDamping, 0.002);
  ASSERT_TRUE(window_->openFiles({kData + "bunny.json"})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("young")->value(), 2e5);
  EXPECT_EQ(material().density, 100.0);
  EXPECT_EQ(material().massDamping, ElasticMaterial{}.massDamping);
}

// The dock's numbers keep the values they are given and read what the user
// types in any notation. With QDoubleSpinBox's fixed decimals the default
// time step ran as 0.0167 s (simulate's is 1/60 s), and a stiffness damping
// of 1e-7 s as 0; the boxes also cut values off at ranges narrower than the
// simulation's (a Young's modulus of 5e13 Pa at 1e13).
TEST_F(Gui, NumberBoxesKeepTheirValuesAndReadAnyNotation) {
  openSample();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().options().timeStep, SimulationOptions{}.timeStep);
  auto type = [&](const char* name, const char* text) {
    auto* box = child<QDoubleSpinBox>(name);
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
    return box->value();
  };
  EXPECT_EQ(type("timeStep", "2.5e-5"), 2.5e-5);
  EXPECT_EQ(type("young", "5E13"), 5e13);
  EXPECT_EQ(type("poisson", "0.49995"), 0.49995);
  EXPECT_EQ(type("stiffnessDamping", "1e-7"), 1e-7);
  EXPECT_EQ(type("density", "x"), ElasticMaterial{}.density);  // refused: unchanged
  EXPECT_EQ(type("poisson", "0.5"), 0.49995);                  // out of (-1, 0.5): unchanged
  // The arrows step by a tenth of the value's magnitude, and from 0 by 1
  // (Qt's adaptive step from 0 is 1e-323).
  auto* gravity = child<QDoubleSpinBox>("gravityX");
  ASSERT_EQ(gravity->value(), 0);
  gravity->stepBy(1);
  EXPECT_EQ(gravity->value(), 1);
  child<QDoubleSpinBox>("density")->stepBy(1);
  EXPECT_EQ(child<QDoubleSpinBox>("density")->value(), ElasticMaterial{}.density + 10);
  gravity->setValue(0);
  // The fur length too (it had 3 decimals: a config's 0.0125 drew as 0.013).
  window_->setRenderPath("fur-cpu");
  child<QDoubleSpinBox>("furLength")->setValue(0.025);
  const double longer = window_->scene().deformable()->fur()->length();
  child<QDoubleSpinBox>("furLength")->setValue(0.0125);
  EXPECT_DOUBLE_EQ(window_->scene().deformable()->fur()->length() / longer, 0.5);
  window_->setRenderPath("cpu");
  // A value shown rounded (0.333333) stays exact when its text is read back.
  auto* push = child<QDoubleSpinBox>("push");
  push->setValue(1.0 / 3);
  EXPECT_EQ(push->text(), "0.333333");
  push->interpretText();
  EXPECT_EQ(push->value(), 1.0 / 3);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const SimulationOptions& options = window_->runner()->simulation().options();
  EXPECT_EQ(options.timeStep, 2.5e-5);
  EXPECT_EQ(options.material.youngsModulus, 5e13);
  EXPECT_EQ(options.material.poissonRatio, 0.49995);
  EXPECT_EQ(options.material.stiffnessDamping, 1e-7);
}

// The dock's solver, tangent and tolerance reach the simulation on Reset.
TEST_F(Gui, SimulationTakesTheDocksSolverTangentAndTolerance) {
  openSample();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().options().solver, SolverKind::Automatic);
  EXPECT_EQ(window_->runner()->simulation().options().tangent, Tangent::Full);
  EXPECT_EQ(window_->runner()->simulation().options().tolerance, SimulationOptions{}.tolerance);
  child<QComboBox>("solver")->setCurrentText("multigrid");
  child<QComboBox>("tangent")->setCurrentText("warped");
  child<QComboBox>("tolerance")->setCurrentText("1e-3");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().options().solver, SolverKind::Multigrid);
  EXPECT_EQ(window_->runner()->simulation().options().tangent, Tangent::Warped);
  EXPECT_EQ(window_->runner()->simulation().options().tolerance, 1e-3);
}

// The dock's fixed base and node list reach the simulation on Reset; a bad
// list is reported with its file and line.
TEST_F(Gui, SimulationHoldsTheBaseShareAndTheListedNodes) {
  openSample();
  child<QComboBox>("scenario")->setCurrentText("sag");
  child<QDoubleSpinBox>("baseShare")->setValue(0);
  child<QLineEdit>("fixedNodes")
      ->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/held_nodes.txt");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().fixedNodes(), (std::vector<int>{0, 1, 2}));
  child<QLineEdit>("fixedNodes")->clear();
  child<QDoubleSpinBox>("baseShare")->setValue(0.1);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  const std::size_t base = window_->runner()->simulation().fixedNodes().size();
  EXPECT_GT(base, 3u);
  const std::filesystem::path bad = scratch("bad_nodes.txt");
  std::ofstream(bad) << "# too far\n99999\n";
  child<QLineEdit>("fixedNodes")->setText(QString::fromStdString(bad.string()));
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_TRUE(window_->lastError().contains("bad_nodes.txt:2: node 99999 does not exist"))
      << window_->lastError().toStdString();
}

// The dock's fixed box holds the nodes inside it, with the listed ones, on
// Reset; it is offered at the level's extent, and one around no node is
// reported, naming the box and the extent.
TEST_F(Gui, SimulationHoldsTheNodesInTheFixedBox) {
  openSample();
  child<QComboBox>("scenario")->setCurrentText("sag");
  child<QDoubleSpinBox>("baseShare")->setValue(0);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_TRUE(window_->runner()->simulation().fixedNodes().empty());
  const Points3 rest = window_->runner()->simulation().restMesh().nodes;
  const BoundingBox extent = boundingBox(rest);
  EXPECT_EQ(child<QDoubleSpinBox>("fixedBoxMiny")->value(), extent.min.y());  // offered
  EXPECT_EQ(child<QDoubleSpinBox>("fixedBoxMaxz")->value(), extent.max.z());
  EXPECT_FALSE(child<QDoubleSpinBox>("fixedBoxMinx")->isEnabled());

  // The left fifth of the body (along x), and the listed nodes.
  child<QCheckBox>("fixedBox")->setChecked(true);
  EXPECT_TRUE(child<QDoubleSpinBox>("fixedBoxMinx")->isEnabled());
  BoundingBox box = extent;
  box.max.x() = extent.min.x() + 0.2 * extent.extent().x();
  child<QDoubleSpinBox>("fixedBoxMaxx")->setValue(box.max.x());
  child<QLineEdit>("fixedNodes")
      ->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/held_nodes.txt");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const std::vector<int> inBox = pointsInBox(rest, box);
  ASSERT_GT(inBox.size(), 3u);
  EXPECT_EQ(window_->runner()->simulation().fixedNodes(), heldWithNodesInBox({0, 1, 2}, rest, box));
  EXPECT_EQ(child<QDoubleSpinBox>("fixedBoxMaxx")->value(), box.max.x());  // kept on Reset

  child<QDoubleSpinBox>("fixedBoxMinx")->setValue(extent.max.x() + 1);
  child<QDoubleSpinBox>("fixedBoxMaxx")->setValue(extent.max.x() + 2);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(window_->runner(), nullptr);
  EXPECT_TRUE(
      window_->lastError().startsWith("the fixed box: no node of the level lies in " +
                                      QString::fromStdString(formatNumber(extent.max.x() + 1))))
      << window_->lastError().toStdString();
  EXPECT_TRUE(window_->lastError().contains(" (the level spans "))
      << window_->lastError().toStdString();
}

// The prescribed nodes (held or driven) are marked on demand: the
// simulation's, and a recorded run's while it is shown.
TEST_F(Gui, MarksThePrescribedNodesOfTheSimulationAndOfARecordedRun) {
  openSample();
  child<QComboBox>("scenario")->setCurrentText("twist");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const std::vector<int> twisted = window_->runner()->simulation().fixedNodes();
  ASSERT_FALSE(twisted.empty());
  EXPECT_EQ(window_->scene().prescribedNodes(), twisted);
  EXPECT_EQ(window_->scene().markedPrescribedCount(), 0);  // (off by default)
  window_->renderNow();
  vtkSmartPointer<vtkImageData> unmarked = window_->grabImage();
  child<QCheckBox>("showPrescribed")->setChecked(true);
  EXPECT_EQ(window_->scene().markedPrescribedCount(), static_cast<Index>(twisted.size()));
  EXPECT_GT(changeFrom(unmarked), 0.001);

  const std::filesystem::path pvd = scratch("twist_run.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  window_->stopRecording();
  child<QComboBox>("scenario")->setCurrentText("drop");  // holds nothing
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().markedPrescribedCount(), 0);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().prescribedNodes(), twisted);  // the run's, while it is shown
  EXPECT_EQ(window_->scene().markedPrescribedCount(), static_cast<Index>(twisted.size()));
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().markedPrescribedCount(), 0);  // the simulation's again
  child<QCheckBox>("showPrescribed")->setChecked(false);
  EXPECT_EQ(window_->scene().markedPrescribedCount(), 0);
}

// The dock shows the parameters of the chosen scenario only (those
// scenariosReading() names), and the run uses them, with its gravity and
// floor.
TEST_F(Gui, SimulationDockOffersAndAppliesTheScenarioParameters) {
  openSample();
  const std::vector<std::pair<const char*, ScenarioParameter>> rows = {
      {"baseShare", ScenarioParameter::BaseShare},
      {"push", ScenarioParameter::PushAcceleration},
      {"pushFrequency", ScenarioParameter::PushFrequency},
      {"dropHeight", ScenarioParameter::DropHeight},
      {"twistDegrees", ScenarioParameter::TwistDegrees},
      {"twistSeconds", ScenarioParameter::TwistSeconds}};
  for (const std::string& name : scenarioNames()) {
    child<QComboBox>("scenario")->setCurrentText(QString::fromStdString(name));
    for (const auto& [row, parameter] : rows)
      EXPECT_EQ(child<QDoubleSpinBox>(row)->isHidden(), !scenarioReads(name, parameter))
          << name << " " << row;
  }
  // No gravity, no push: a wobble that stays at rest.
  child<QComboBox>("scenario")->setCurrentText("wobble");
  for (const char* axis : {"gravityX", "gravityY", "gravityZ"})
    child<QDoubleSpinBox>(axis)->setValue(0);
  child<QDoubleSpinBox>("push")->setValue(0);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().options().gravity, Eigen::Vector3d::Zero());
  for (int i = 0; i < 3; ++i) child<QPushButton>("step")->click();
  const Simulation& still = window_->runner()->simulation();
  EXPECT_LT((still.state().positions - still.restMesh().nodes).norm(), 1e-12);
  // Drop from height 0 with the default floor: the body starts on it.
  child<QComboBox>("scenario")->setCurrentText("drop");
  child<QDoubleSpinBox>("dropHeight")->setValue(0);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const Simulation& dropped = window_->runner()->simulation();
  ASSERT_TRUE(dropped.options().floorHeight.has_value());
  EXPECT_NEAR(dropped.state().positions.col(1).minCoeff(), *dropped.options().floorHeight, 1e-12);
  // A floor set through the body: used, and warned of.
  const double bottom = dropped.restMesh().nodes.col(1).minCoeff();
  const double top = dropped.restMesh().nodes.col(1).maxCoeff();
  child<QComboBox>("scenario")->setCurrentText("sag");
  child<QCheckBox>("floor")->setChecked(true);
  EXPECT_EQ(child<QDoubleSpinBox>("floorHeight")->value(), bottom);  // offered
  child<QDoubleSpinBox>("floorHeight")->setValue((bottom + top) / 2);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(*window_->runner()->simulation().options().floorHeight, (bottom + top) / 2);
  EXPECT_TRUE(window_->statusBar()->currentMessage().contains("nodes start below the floor"))
      << window_->statusBar()->currentMessage().toStdString();
  // Loads from a file act in every step.
  child<QCheckBox>("floor")->setChecked(false);
  child<QLineEdit>("loads")->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/loads.txt");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  child<QPushButton>("step")->click();
  const Points3 forces = window_->runner()->simulation().externalForces();
  EXPECT_EQ(forces.row(20), Eigen::RowVector3d(0, -2, 0));
  EXPECT_EQ(forces.colwise().sum(), Eigen::RowVector3d(0, -3, 0));
  // ... for as long as asked, then let go.
  child<QDoubleSpinBox>("loadSeconds")->setValue(0.01);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  child<QPushButton>("step")->click();
  EXPECT_EQ(window_->runner()->simulation().externalForces().colwise().sum(),
            Eigen::RowVector3d(0, -3, 0));
  child<QPushButton>("step")->click();  // starts at 1/60 s > 0.01 s
  EXPECT_EQ(window_->runner()->simulation().externalForces().norm(), 0.0);
  // ... scaled over time by a load curve (0 at 0 s, 1 at 0.03 s).
  child<QDoubleSpinBox>("loadSeconds")->setValue(0);  // the whole run
  child<QLineEdit>("loadCurve")
      ->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/load_curve.txt");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  for (int i = 0; i < 3; ++i) {
    const double start = window_->runner()->simulation().time();  // 0, dt, 2 dt > 0.03
    child<QPushButton>("step")->click();
    EXPECT_NEAR(window_->runner()->simulation().externalForces().colwise().sum().y(),
                -3 * std::min(start / 0.03, 1.0), 1e-12)
        << "step " << i;
  }
  // A bad curve is an error naming its file and line, and no run starts.
  child<QLineEdit>("loadCurve")
      ->setText(QString(TETSKIN_SOURCE_DIR) + "/tests/data/bad_load_curve.txt");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_TRUE(window_->lastError().contains("bad_load_curve.txt:4: the times must increase"))
      << window_->lastError().toStdString();
}

// A dataset whose config says z is up: gravity left at the standard pull
// turns down z, the floor's height is along z, and the run is upright along
// it; a gravity the user set stays as set. The View dock's up axis does the
// same for a dataset whose config does not say.
TEST_F(Gui, ADatasetsUpAxisTurnsGravityAndTheFloor) {
  const std::filesystem::path folder = scratch("up_z");
  std::filesystem::create_directories(folder);
  for (const char* file : {"bunny.node", "bunny.ele", "bunny.obj"})
    std::filesystem::copy_file(kData.toStdString() + file, folder / file,
                               std::filesystem::copy_options::overwrite_existing);
  std::ifstream in(kData.toStdString() + "bunny.json");
  std::stringstream config;
  config << in.rdbuf();
  std::string text = config.str();
  text.insert(text.find('{') + 1, "\n  \"up\": \"z\",");
  std::ofstream(folder / "bunny.json") << text;

  ASSERT_TRUE(window_->openFiles({QString::fromStdString((folder / "bunny.json").string())}))
      << window_->lastError().toStdString();
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("gravityY")->value(), 0);
  EXPECT_EQ(child<QDoubleSpinBox>("gravityZ")->value(), -kStandardGravity);
  EXPECT_EQ(child<QCheckBox>("floor")->text(), "at z =");
  EXPECT_EQ(child<QComboBox>("up")->currentText(), "z");
  const Simulation& sim = window_->runner()->simulation();
  EXPECT_EQ(sim.options().up, UpAxis::Z);
  EXPECT_EQ(sim.options().gravity, Eigen::Vector3d(0, 0, -kStandardGravity));
  EXPECT_NEAR(child<QDoubleSpinBox>("floorHeight")->value(), sim.restMesh().nodes.col(2).minCoeff(),
              1e-4);
  // Back to the y-up sample: the standard pull follows; a set one stays.
  openSample();
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(child<QDoubleSpinBox>("gravityY")->value(), -kStandardGravity);
  EXPECT_EQ(child<QCheckBox>("floor")->text(), "at y =");
  EXPECT_EQ(child<QComboBox>("up")->currentText(), "y");
  // The View dock's up axis turns a dataset whose config does not say: the
  // camera and the next run follow it.
  window_->renderNow();
  vtkSmartPointer<vtkImageData> upright = window_->grabImage();
  child<QComboBox>("up")->setCurrentText("z");
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->simulation().options().up, UpAxis::Z);
  EXPECT_EQ(child<QDoubleSpinBox>("gravityZ")->value(), -kStandardGravity);
  EXPECT_GT(changeFrom(upright), 0.05);  // seen from another side
  child<QComboBox>("up")->setCurrentText("y");
  EXPECT_EQ(child<QDoubleSpinBox>("gravityY")->value(), -kStandardGravity);
  child<QDoubleSpinBox>("gravityY")->setValue(-1.62);  // the Moon
  ASSERT_TRUE(window_->openFiles({QString::fromStdString((folder / "bunny.json").string())}));
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(child<QDoubleSpinBox>("gravityY")->value(), -1.62);
  EXPECT_EQ(child<QDoubleSpinBox>("gravityZ")->value(), 0);
}

TEST_F(Gui, ShiftDragPullsTheBody) {
  openSample();
  child<QComboBox>("scenario")->setCurrentText("sag");
  child<QComboBox>("controlStyle")->setCurrentText("none");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  window_->grabImage();
  QWidget* view = window_->view();
  const QPoint from(view->width() / 2, view->height() / 2);
  mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::ShiftModifier);
  const std::optional<Index> grabbed = window_->scene().pickedVertex();
  ASSERT_TRUE(grabbed.has_value());
  const Eigen::Vector2d before = project(window_->scene().vertexInfo(*grabbed).position);
  mouse(QEvent::MouseMove, from + QPoint(60, 0), Qt::LeftButton, Qt::ShiftModifier);
  EXPECT_TRUE(window_->runner()->playing());
  const Index start = window_->runner()->steps();
  EXPECT_TRUE(QTest::qWaitFor([&] { return window_->runner()->steps() >= start + 12; }, 30000));
  mouse(QEvent::MouseButtonRelease, from + QPoint(60, 0), Qt::NoButton, Qt::ShiftModifier);
  const Index released = window_->runner()->steps();
  EXPECT_TRUE(QTest::qWaitFor([&] { return window_->runner()->steps() >= released + 2; }, 30000));
  EXPECT_EQ(window_->runner()->simulation().externalForces().norm(), 0.0);  // let go
  window_->showLatestState();
  const Eigen::Vector2d after = project(window_->scene().vertexInfo(*grabbed).position);
  std::printf("pulled vertex moved %.1f px right, %.1f px up\n", after.x() - before.x(),
              after.y() - before.y());
  EXPECT_GT(after.x() - before.x(), 2.0);  // toward the mouse
}

TEST_F(Gui, ExportsFramesAndRecordsARunThatReload) {
  openSample();
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const std::filesystem::path vtu = scratch("frame.vtu"), vtp = scratch("frame.vtp");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtu.string())));
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtp.string())));
  const auto grid = readVtu(vtu);
  EXPECT_EQ(grid->GetNumberOfPoints(), 3270);
  EXPECT_EQ(grid->GetNumberOfCells(), 12713);
  const BoundSurface back = readBinding(vtp);
  EXPECT_EQ(back.surface.vertexCount(), 1839);
  EXPECT_EQ(back.binding.controlIds, window_->scene().binding().controlIds);
  // Its dataset, named from the file's folder, is the one the window opened.
  EXPECT_TRUE(std::filesystem::equivalent(back.dataset, window_->scene().datasetPath()))
      << back.dataset;
  // The file's points are the deformed surface; the binding's rest shape
  // comes back from its Displacement array.
  ASSERT_TRUE(back.deformed.has_value());
  EXPECT_TRUE(back.deformed->positions.isApprox(window_->scene().deformedPositions()));
  EXPECT_LT((back.surface.positions - window_->scene().surface().positions).cwiseAbs().maxCoeff(),
            1e-12);
  const std::filesystem::path pvd = scratch("run.pvd");
  std::filesystem::remove_all(scratch("run_frames"));
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->recordedFrames(), 3);  // the first frame and two steps
  window_->stopRecording();
  std::stringstream text;
  text << std::ifstream(pvd).rdbuf();
  std::size_t entries = 0;
  for (std::size_t at = text.str().find("<DataSet"); at != std::string::npos;
       at = text.str().find("<DataSet", at + 1))
    ++entries;
  EXPECT_EQ(entries, 6u);  // control mesh and surface per frame
  EXPECT_EQ(readVtu(scratch("run_frames/control_00002.vtu"))->GetNumberOfCells(), 12713);
  EXPECT_FALSE(window_->exportFrame(QString::fromStdString(scratch("frame.txt").string())));
  // File > Open takes the exported surface back as a binding, as it is: its
  // ids, level and rest shape, not a new binding of its deformed positions.
  ASSERT_TRUE(window_->openFile(QString::fromStdString(vtp.string())))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().binding().controlIds, back.binding.controlIds);
  EXPECT_EQ(window_->scene().level(), back.binding.level);
  EXPECT_TRUE(window_->scene().surface().positions.isApprox(back.surface.positions));
}

// A binding opened with no dataset open brings its own (named from the
// binding's folder); a plain surface cannot, nor a binding whose dataset
// is gone.
TEST_F(Gui, ABindingOpensWithItsOwnDataset) {
  openSample();
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const std::filesystem::path vtp = scratch("own_dataset.vtp");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtp.string())));
  const SurfaceBinding exported = window_->scene().binding();
  window_ = std::make_unique<MainWindow>(false);
  EXPECT_FALSE(window_->openFile(kData + "bunny.obj"));
  EXPECT_TRUE(window_->lastError().contains("open a dataset before a surface"))
      << window_->lastError().toStdString();
  EXPECT_FALSE(window_->openFile(QString(TETSKIN_SOURCE_DIR) +
                                 "/tests/data/binding_of_a_missing_dataset.vtp"));
  EXPECT_TRUE(
      window_->lastError().contains("names its dataset " + QString(TETSKIN_SOURCE_DIR) +
                                    "/tests/data/no_such_folder/bunny.json, which is not there"))
      << window_->lastError().toStdString();
  EXPECT_FALSE(window_->scene().hasDataset());
  ASSERT_TRUE(window_->openFile(QString::fromStdString(vtp.string())))
      << window_->lastError().toStdString();
  ASSERT_TRUE(window_->scene().hasDataset());
  EXPECT_TRUE(std::filesystem::equivalent(window_->scene().datasetPath(),
                                          (kData + "bunny.json").toStdString()));
  EXPECT_EQ(window_->scene().binding().controlIds, exported.controlIds);
  EXPECT_EQ(window_->scene().level(), exported.level);
}

// From frame... (and File > Open of a .vtu) starts the simulation again from
// an exported frame's positions and velocities; a frame of another level is
// refused naming its file and leaves the running simulation as it was; Reset
// ends a recording, whose series keeps the frames so far.
TEST_F(Gui, StartsFromAFrameAndResetEndsARecording) {
  const std::filesystem::path frame = scratch("start.vtu");
  EXPECT_FALSE(window_->startFromFrame(QString::fromStdString(frame.string())));
  EXPECT_NE(window_->lastError().indexOf("open a dataset"), -1);
  openSample();
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(frame.string())));
  const SimulationState exported = window_->runner()->state();
  EXPECT_GT(exported.velocities.norm(), 0.0);
  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const auto startsFromTheFrame = [&](const char* how) {
    const SimulationState s = window_->runner()->state();
    EXPECT_EQ(s.steps, 0) << how;
    EXPECT_EQ(s.time, 0.0) << how;
    EXPECT_LE((s.positions - exported.positions).cwiseAbs().maxCoeff(), 1e-12) << how;
    EXPECT_LE((s.velocities - exported.velocities).cwiseAbs().maxCoeff(), 1e-12) << how;
    const LevelRange& range = window_->scene().dataset().mesh.levels[2];  // the simulated level
    EXPECT_LE((window_->scene().controlNodes().middleRows(range.firstNode, range.nodeCount) -
               exported.positions)
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12)
        << how;  // and the view shows it
  };
  ASSERT_TRUE(window_->startFromFrame(QString::fromStdString(frame.string())))
      << window_->lastError().toStdString();
  startsFromTheFrame("startFromFrame");
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->steps(), 1);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(frame.string())))
      << window_->lastError().toStdString();
  startsFromTheFrame("File > Open");

  // A frame of level 0 while level 2 is simulated.
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const Points3 before = window_->runner()->state().positions;
  const TetMesh coarse = extractLevel(window_->scene().dataset().mesh, 0);
  const std::filesystem::path other = scratch("level0.vtu");
  writeVtu(other, simulationFrame(coarse, test::unloadedFrame(coarse, coarse.nodes), 0));
  EXPECT_FALSE(window_->startFromFrame(QString::fromStdString(other.string())));
  EXPECT_NE(window_->lastError().indexOf("level0.vtu: has 224 points and 598 tetrahedra"), -1)
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->steps(), 1);
  EXPECT_EQ(window_->runner()->state().positions, before);

  const std::filesystem::path pvd = scratch("reset_run.pvd");
  std::filesystem::remove_all(scratch("reset_run_frames"));
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->recordedFrames(), 2);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(window_->recordedFrames(), 0);
  EXPECT_FALSE(child<QPushButton>("record")->isChecked());
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(PvdSeries::read(pvd).size(), 4u);  // two frames, control mesh and surface each
}

// A recorded run opened in the window (File > Open of its .pvd) is stepped
// through with the Recorded run slider: each frame shows the state the run
// had (the frames hold it exactly), the live simulation is not drawn over
// it, and Continue from here simulates on from the frame shown. A run of
// another level is refused with its file, changing nothing, and a rebind to
// another level closes an open run.
TEST_F(Gui, ARecordedRunIsSteppedThroughAndContinuedFrom) {
  openSample();
  const std::filesystem::path pvd = scratch("replay.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  std::vector<Points3> states{window_->runner()->state().positions};
  for (int i = 0; i < 2; ++i) {
    QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
    states.push_back(window_->runner()->state().positions);
  }
  window_->stopRecording();
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  QTest::mouseClick(child<QPushButton>("play"), Qt::LeftButton);
  QTest::qWait(100);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  EXPECT_FALSE(window_->runner()->playing());  // paused by the frame shown
  EXPECT_FALSE(child<QPushButton>("play")->isChecked());
  EXPECT_FALSE(child<QGroupBox>("recordedRun")->isHidden());
  EXPECT_TRUE(child<QGroupBox>("recordedRun")->isVisibleTo(window_.get()));  // its dock raised
  auto* slider = child<QSlider>("runFrame");
  EXPECT_EQ(slider->maximum(), 2);
  const LevelRange range = window_->scene().dataset().mesh.levels[2];
  auto shown = [&] {
    return Points3(window_->scene().controlNodes().middleRows(range.firstNode, range.nodeCount));
  };
  QTest::qWait(100);  // the window's timer runs: it does not draw the live state over the frame
  EXPECT_EQ(shown(), states[0]);
  slider->setValue(2);
  EXPECT_EQ(shown(), states[2]);
  EXPECT_EQ(child<QLabel>("runLabel")->text(), "frame 2 of 2, t = 0.0333333 s");
  // Export writes what is shown: the frame's control mesh and surface.
  const std::filesystem::path vtu = scratch("replayed.vtu"), vtp = scratch("replayed.vtp");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtu.string())));
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtp.string())));
  EXPECT_EQ(
      readSimulationFrame(vtu, window_->runner()->simulation().restMesh(), "level 2").positions,
      states[2]);
  EXPECT_EQ(readBinding(vtp, window_->scene().dataset().mesh).deformed->positions,
            window_->scene().deformedPositions());
  // Film... writes every frame as the view shows it, at the recorded rate;
  // the frame shown before is shown again. Decoded, the film's first frame
  // is the view at frame 0.
  const std::filesystem::path film = scratch("replay.ogv");
  std::filesystem::remove(film);
  ASSERT_TRUE(window_->filmRun(QString::fromStdString(film.string())))
      << window_->lastError().toStdString();
  EXPECT_EQ(slider->value(), 2);
  EXPECT_EQ(shown(), states[2]);
  EXPECT_TRUE(window_->statusBar()->currentMessage().endsWith("(3 frames at 60 frames/s)"))
      << window_->statusBar()->currentMessage().toStdString();
  const test::DecodedMovie movie = test::decodeMovie(film);
  EXPECT_EQ(movie.frames, 3);
  slider->setValue(0);
  vtkSmartPointer<vtkImageData> view = window_->grabImage();
  EXPECT_LT(test::meanLumaDifference(movie.firstLuma, movie.width, movie.height, view), 1.5);
  slider->setValue(2);
  EXPECT_FALSE(window_->filmRun(QString::fromStdString(scratch("replay.avi").string())));
  EXPECT_TRUE(window_->lastError().endsWith("the name must end in .ogv"));
  EXPECT_FALSE(std::filesystem::exists(scratch("replay.avi")));
  // Play steps through the frames at their recorded times, from the start
  // again when at the end, and stops at the last.
  auto* play = child<QPushButton>("runPlay");
  QTest::mouseClick(play, Qt::LeftButton);
  EXPECT_EQ(slider->value(), 0);
  EXPECT_EQ(shown(), states[0]);
  EXPECT_TRUE(QTest::qWaitFor([&] { return !play->isChecked(); }, 5000));
  EXPECT_EQ(slider->value(), 2);
  EXPECT_EQ(shown(), states[2]);
  QTest::mouseClick(play, Qt::LeftButton);                        // (from frame 0 again)
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);  // the live state again
  EXPECT_FALSE(play->isChecked());
  slider->setValue(2);
  QTest::mouseClick(child<QPushButton>("runContinue"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->state().positions, states[2]);
  EXPECT_EQ(window_->runner()->steps(), 0);
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_NE(shown(), states[2]);  // the live state again

  child<QSpinBox>("rebindLevel")->setValue(1);
  QTest::mouseClick(child<QPushButton>("rebind"), Qt::LeftButton);
  EXPECT_TRUE(child<QGroupBox>("recordedRun")->isHidden());
  EXPECT_FALSE(window_->openFile(QString::fromStdString(pvd.string())));
  EXPECT_EQ(window_->lastError().toStdString(),
            pvd.string() +
                ": its frames are of level 2; the simulated level is 1: rebind the surface to "
                "level 2 (Binding dock) first");
  EXPECT_TRUE(child<QGroupBox>("recordedRun")->isHidden());
}

// A recorded run opened with no dataset open brings its dataset and
// surface, named by its first surface frame (a binding), as a binding
// brings its dataset: one file replays the run. A run without surface
// frames cannot say its dataset.
TEST_F(Gui, ARecordedRunBringsItsDatasetAndSurface) {
  openSample();
  const std::filesystem::path pvd = scratch("own_dataset_run.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const Points3 stepped = window_->runner()->state().positions;
  const std::filesystem::path dataset = window_->scene().datasetPath();
  const SurfaceBinding binding = window_->scene().binding();
  window_->stopRecording();
  window_ = std::make_unique<MainWindow>(false);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  EXPECT_TRUE(std::filesystem::equivalent(window_->scene().datasetPath(), dataset));
  EXPECT_EQ(window_->scene().binding().controlIds, binding.controlIds);
  child<QSlider>("runFrame")->setValue(1);
  const LevelRange range = window_->scene().dataset().mesh.levels[2];
  EXPECT_EQ(Points3(window_->scene().controlNodes().middleRows(range.firstNode, range.nodeCount)),
            stepped);

  PvdSeries controlOnly(scratch("control_only.pvd"));
  controlOnly.add(0, 0, pvd.stem().string() + "_frames/control_00000.vtu");
  controlOnly.write();
  window_ = std::make_unique<MainWindow>(false);
  EXPECT_FALSE(window_->openFile(QString::fromStdString(scratch("control_only.pvd").string())));
  EXPECT_EQ(window_->lastError().toStdString(),
            scratch("control_only.pvd").string() +
                ": has no surface frames naming its dataset: open the dataset first");
}

// The floor a drop lands on is drawn under the body (and recorded with a
// run, whose replay draws it); a scenario without one has none drawn.
TEST_F(Gui, DrawsTheFloorOfTheSimulationAndOfARecordedRun) {
  openSample();
  EXPECT_EQ(window_->scene().floor(), std::nullopt);  // wobble
  child<QComboBox>("scenario")->setCurrentText("drop");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const std::optional<FloorPlane> floor = window_->runner()->simulation().options().floor();
  ASSERT_TRUE(floor.has_value());
  EXPECT_EQ(window_->scene().floor(), floor);
  const std::filesystem::path pvd = scratch("drop_run.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  window_->stopRecording();
  child<QComboBox>("scenario")->setCurrentText("wobble");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().floor(), std::nullopt);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().floor(), floor);  // the run's, while it is shown
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().floor(), std::nullopt);  // the simulation's again
}

// A drop starts above the rest shape: the camera moves back (its direction
// kept) until the lifted body is in view; a start the camera shows already
// leaves it where it is.
TEST_F(Gui, KeepsADropsLiftedStartInView) {
  openSample();
  vtkCamera* camera = window_->renderer()->GetActiveCamera();
  Eigen::Vector3d position, direction;
  camera->GetPosition(position.data());
  camera->GetDirectionOfProjection(direction.data());
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);  // wobble: at rest
  Eigen::Vector3d after;
  camera->GetPosition(after.data());
  EXPECT_EQ(after, position);
  child<QComboBox>("scenario")->setCurrentText("drop");
  child<QDoubleSpinBox>("dropHeight")->setValue(1.5);
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const BoundingBox start = boundingBox(window_->runner()->simulation().state().positions);
  const std::array<double, 6> bounds = toVtkBounds(start);
  EXPECT_TRUE(boundsInView(window_->renderer(), bounds.data()));
  Eigen::Vector3d turned;
  camera->GetDirectionOfProjection(turned.data());
  EXPECT_NEAR((turned - direction).norm(), 0, 1e-12);
}

// The frame statistics overlay is the View menu's to switch, and the menu
// shows whether it is on however it was switched.
TEST_F(Gui, TheViewMenuSwitchesTheFrameStatistics) {
  openSample();
  auto* action = window_->findChild<QAction*>("overlayAction");
  ASSERT_NE(action, nullptr);
  EXPECT_FALSE(action->isChecked());  // (the fixture switched it off)
  action->trigger();
  EXPECT_TRUE(window_->overlayVisible());
  EXPECT_TRUE(action->isChecked());
  window_->setOverlayVisible(false);
  EXPECT_FALSE(action->isChecked());
}

// The Simulation dock plots the energies of every step taken: a drop
// gains kinetic energy as it falls; Reset starts the curves again.
TEST_F(Gui, PlotsTheEnergyOfEachStep) {
  openSample();
  auto* plot = window_->findChild<EnergyPlot*>("energyPlot");
  ASSERT_NE(plot, nullptr);
  child<QComboBox>("scenario")->setCurrentText("drop");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_EQ(plot->samples().size(), 1u);  // the start
  EXPECT_EQ(plot->samples().front().time, 0);
  EXPECT_EQ(plot->samples().front().kinetic, 0);
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  ASSERT_EQ(plot->samples().size(), 4u);
  const Energies now = window_->runner()->simulation().energies();
  EXPECT_EQ(plot->samples().back().kinetic, now.kinetic);
  EXPECT_EQ(plot->samples().back().elastic, now.elastic);
  EXPECT_EQ(plot->samples().back().gravitational, now.gravitational);
  // A drop starts lifted above its rest shape and loses height each step.
  EXPECT_GT(plot->samples().front().gravitational, 0);
  EXPECT_NEAR(plot->samples().back().time, 3 * window_->runner()->simulation().options().timeStep,
              1e-12);
  for (std::size_t i = 1; i < plot->samples().size(); ++i) {
    EXPECT_GT(plot->samples()[i].kinetic, plot->samples()[i - 1].kinetic) << "falling, step " << i;
    EXPECT_LT(plot->samples()[i].gravitational, plot->samples()[i - 1].gravitational) << i;
    // Damping takes energy away; nothing adds any.
    EXPECT_LT(plot->samples()[i].total(), plot->samples()[i - 1].total()) << i;
  }
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(plot->samples().size(), 1u);
  // Started from a frame: the plot's start is the frame's state.
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const Energies beforeFrame = window_->runner()->simulation().energies();
  const std::filesystem::path frame = scratch("energy_frame.vtu");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(frame.string())))
      << window_->lastError().toStdString();
  ASSERT_TRUE(window_->startFromFrame(QString::fromStdString(frame.string())))
      << window_->lastError().toStdString();
  ASSERT_EQ(plot->samples().size(), 1u);
  EXPECT_EQ(plot->samples().front().kinetic, window_->runner()->simulation().energies().kinetic);
  EXPECT_GT(plot->samples().front().kinetic, 0);
  // Measured from the rest shape, the frame's gravitational energy is the
  // one the run that wrote it had there: the curves carry on.
  EXPECT_NEAR(plot->samples().front().gravitational, beforeFrame.gravitational,
              1e-9 * beforeFrame.gravitational);
}

// The Simulation dock says what the supports carry, sampled with the
// energy: a sag's held base at the start (each held node's own weight, up),
// then at each step taken; a drop holds no node.
TEST_F(Gui, ShowsWhatTheSupportsCarry) {
  openSample();
  auto* supports = child<QLabel>("supports");
  child<QComboBox>("scenario")->setCurrentText("sag");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  const Simulation& sim = window_->runner()->simulation();
  const std::size_t held = sim.fixedNodes().size();
  ASSERT_GT(held, 0u);
  const auto expected = [&] {
    const Eigen::Vector3d reaction =
        sim.reactionForces(window_->runner()->state()).colwise().sum().transpose();
    return "Supports: reaction " + commaSeparatedToScale(reaction) + " N on " +
           std::to_string(held) + " prescribed nodes";
  };
  EXPECT_EQ(supports->text().toStdString(), expected());
  const Eigen::VectorXd masses = sim.nodeMasses();
  double heldWeight = 0;
  for (int node : sim.fixedNodes()) heldWeight += masses[node] * 9.81;
  const Eigen::Vector3d atRest =
      sim.reactionForces(window_->runner()->state()).colwise().sum().transpose();
  EXPECT_NEAR(atRest.y(), heldWeight, 1e-9 * heldWeight);
  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(supports->text().toStdString(), expected());
  EXPECT_NE(supports->text().toStdString(), "Supports: reaction " + commaSeparatedToScale(atRest) +
                                                " N on " + std::to_string(held) +
                                                " prescribed nodes");
  child<QComboBox>("scenario")->setCurrentText("drop");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_EQ(supports->text().toStdString(), "Supports: none (no node held or driven)");
}

// Values read to their meaningful digits (#52 item 7): at rest the energies
// are round-off and read 0, and the sag's supports carry the held weight up
// and nothing sideways, with the digits of the weight and no more.
TEST_F(Gui, ReadsRoundOffAsZero) {
  openSample();
  child<QComboBox>("scenario")->setCurrentText("sag");
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  auto* plot = child<EnergyPlot>("energyPlot");
  ASSERT_FALSE(plot->samples().empty());
  const QStringList legend = plot->legend();
  ASSERT_EQ(legend.size(), 4);
  EXPECT_EQ(legend[0].toStdString(), "kinetic 0");
  EXPECT_EQ(legend[1].toStdString(), "elastic 0");
  EXPECT_EQ(legend[2].toStdString(), "gravitational 0");
  const std::string supports = child<QLabel>("supports")->text().toStdString();
  EXPECT_TRUE(std::regex_match(
      supports,
      std::regex(
          R"(Supports: reaction 0,[0-9]+(\.[0-9]+)?(e[-+][0-9]+)?,0 N on [0-9]+ prescribed nodes)")))
      << supports;
  // A step later the body moves: the energies read as numbers again.
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_NE(plot->legend()[1].toStdString(), "elastic 0");
}

// At 1280x800, as a new user first sees it (#52 item 7): no dock scrolls
// sideways, whichever tab is raised, and the 3D view is the largest thing
// on screen.
TEST_F(Gui, DocksFitA1280x800WindowWithoutScrollingSideways) {
  window_.reset();
  MainWindow window(false);
  window.setOverlayVisible(false);
  window.resize(1280, 800);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openFiles({kData + "bunny.json", kData + "bunny.obj"}))
      << window.lastError().toStdString();
  for (const char* name : {"ViewDock", "SimulationDock", "BindingDock"}) {
    auto* dock = window.findChild<QDockWidget*>(name);
    ASSERT_NE(dock, nullptr) << name;
    dock->raise();
    QApplication::processEvents();
    auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
    ASSERT_NE(scroll, nullptr) << name;
    EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible()) << name << " scrolls sideways";
    EXPECT_LE(scroll->widget()->minimumSizeHint().width(), scroll->viewport()->width())
        << name << "'s fields are cut off";
    EXPECT_GT(window.view()->width(), dock->width()) << name;
  }
  window.saveScreenshot(QString(TETSKIN_ACTUAL_DIR) + "/window_1280x800.png", true);
}

// A Gmsh mesh opens as a dataset of one level, and simulates.
TEST_F(Gui, OpensAGmshMesh) {
  ASSERT_TRUE(
      window_->openFile(QString(TETSKIN_SOURCE_DIR) + "/tests/data/gmsh/sphere_coarse_v41.msh"))
      << window_->lastError().toStdString();
  ASSERT_EQ(window_->scene().dataset().mesh.levels.size(), 1u);
  EXPECT_EQ(window_->scene().dataset().mesh.levels[0].elementCount, 679);
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->state().steps, 1);
}

// Opening a binding of another level moves the control mesh to that level,
// as a rebind does, and the control level field says so.
// A control level other than the simulated one follows it: a rigid motion
// of the simulated level moves the shown level's nodes (and the drawn mesh)
// rigidly, and simulated steps move them.
TEST_F(Gui, AnotherControlLevelFollowsTheSimulatedLevel) {
  openSample();
  Scene& scene = window_->scene();
  ASSERT_EQ(scene.level(), 2);
  child<QSpinBox>("controlLevel")->setValue(0);
  ASSERT_EQ(scene.controlLevel(), 0);
  const MultiLevelTetMesh& mesh = scene.dataset().mesh;
  const LevelRange& shown = mesh.levels[0];
  const LevelRange& simulated = mesh.levels[2];
  const Points3 shownRest = mesh.nodes.middleRows(shown.firstNode, shown.nodeCount);
  EXPECT_LT((scene.shownControlPositions() - shownRest).cwiseAbs().maxCoeff(), 1e-12);

  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(0.4, -1.2, 2.0);
  auto moved = [&](const Points3& p) -> Points3 {
    return (p * turn.transpose()).rowwise() + shift;
  };
  scene.showControlState(moved(mesh.nodes.middleRows(simulated.firstNode, simulated.nodeCount)));
  const Points3 expected = moved(shownRest);
  const double size = (shownRest.colwise().maxCoeff() - shownRest.colwise().minCoeff()).norm();
  EXPECT_LT((scene.shownControlPositions() - expected).cwiseAbs().maxCoeff(), 1e-9 * size);
  // What is drawn: the control actor is the renderer's actor whose bounds
  // are those of the moved level.
  double drawnBounds[6] = {0, 0, 0, 0, 0, 0};
  bool found = false;
  vtkActorCollection* actors = window_->renderer()->GetActors();
  actors->InitTraversal();
  for (vtkActor* a = actors->GetNextActor(); a; a = actors->GetNextActor())
    if (a != scene.surfaceActor() && a->GetVisibility() && a->GetMapper()->GetInput() &&
        a->GetMapper()->GetInput()->GetNumberOfPoints() == shown.nodeCount) {
      a->GetBounds(drawnBounds);
      found = true;
    }
  ASSERT_TRUE(found);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(drawnBounds[2 * k], expected.col(k).minCoeff(), 1e-9 * size) << k;
    EXPECT_NEAR(drawnBounds[2 * k + 1], expected.col(k).maxCoeff(), 1e-9 * size) << k;
  }

  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  EXPECT_LT((scene.shownControlPositions() - shownRest).cwiseAbs().maxCoeff(), 1e-12);
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_GT((scene.shownControlPositions() - shownRest).cwiseAbs().maxCoeff(), 1e-6 * size);
}

TEST_F(Gui, OpeningABindingShowsTheControlMeshOfItsLevel) {
  openSample();
  child<QSpinBox>("rebindLevel")->setValue(1);
  QTest::mouseClick(window_->findChild<QPushButton*>("rebind"), Qt::LeftButton);
  ASSERT_EQ(window_->scene().level(), 1) << window_->lastError().toStdString();
  const std::filesystem::path vtp = scratch("level1.vtp");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(vtp.string())));
  child<QSpinBox>("rebindLevel")->setValue(2);
  QTest::mouseClick(window_->findChild<QPushButton*>("rebind"), Qt::LeftButton);
  ASSERT_EQ(window_->scene().controlLevel(), 2);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(vtp.string())))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().level(), 1);
  EXPECT_EQ(window_->scene().controlLevel(), 1);
  EXPECT_EQ(child<QSpinBox>("controlLevel")->value(), 1);
}

TEST_F(Gui, BindingDiagnosticsColourHighlightAndRebind) {
  openSample();
  child<QComboBox>("colorBy")->setCurrentText("MinBarycentric");
  EXPECT_EQ(window_->scene().colorBy(), ColorBy::MinBarycentric);
  EXPECT_TRUE(window_->scene().surfaceActor()->GetMapper()->GetScalarVisibility());
  const auto* histogram = child<HistogramWidget>("histogram");
  int total = 0;
  for (int c : histogram->counts()) total += c;
  EXPECT_EQ(total, 1839);
  EXPECT_DOUBLE_EQ(histogram->low(), window_->scene().binding().minBarycentric.minCoeff());
  child<QCheckBox>("highlight")->setChecked(true);
  const SurfaceBinding& b = window_->scene().binding();
  const BindingSummary& s = window_->scene().summary();
  Index expected = 0;
  for (Index v = 0; v < b.vertexCount(); ++v)
    expected += b.minBarycentric[v] < 0 || std::abs(b.distance[v]) > s.distanceP99 * s.diagonal;
  EXPECT_EQ(window_->scene().highlightedCount(), expected);
  EXPECT_GT(expected, 0);
  child<QComboBox>("rebindMethod")->setCurrentText("seed");
  child<QSpinBox>("rebindLevel")->setValue(1);
  QTest::mouseClick(window_->findChild<QPushButton*>("rebind"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().binding().method, BindingMethod::Seed);
  EXPECT_EQ(window_->scene().level(), 1);
  EXPECT_EQ(window_->runner()->simulation().level(), 1);  // the simulation follows
  EXPECT_TRUE(window_->scene().previousSummary().has_value());
  EXPECT_TRUE(child<QLabel>("comparison")->text().contains("before:"));
  // Embed on the GPU paths too.
  window_->setRenderPath("gpu-1pass");
  child<QComboBox>("rebindMethod")->setCurrentText("embed");
  QTest::mouseClick(window_->findChild<QPushButton*>("rebind"), Qt::LeftButton);
  EXPECT_EQ(window_->scene().binding().method, BindingMethod::Embed)
      << window_->lastError().toStdString();
  window_->setRenderPath("gpu-2pass");
  EXPECT_EQ(window_->scene().binding().method, BindingMethod::Embed)
      << window_->lastError().toStdString();
}

// Stress on the skin: colouring by it takes the simulation's frame, carried
// through the binding; at rest there is none, once pushed there is.
TEST_F(Gui, ColoursTheSkinByTheStressOfTheSimulatedLevel) {
  openSample();
  child<QComboBox>("colorBy")->setCurrentText("VonMisesStress");
  ASSERT_EQ(window_->scene().colorBy(), ColorBy::VonMisesStress);
  vtkMapper* mapper = window_->scene().surfaceActor()->GetMapper();
  EXPECT_TRUE(mapper->GetScalarVisibility());
  for (int i = 0; i < 8; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const SimulationSession& session = window_->runner()->session();
  const Eigen::VectorXd expected =
      session
          .surfaceFields(session.simulation().frameFields(session.state()),
                         window_->scene().binding())[0]
          .values;
  ASSERT_GT(expected.maxCoeff(), 0);
  EXPECT_EQ(std::string(mapper->GetArrayName()), "VonMisesStress");
  EXPECT_DOUBLE_EQ(mapper->GetScalarRange()[1], expected.maxCoeff());
  child<QComboBox>("colorBy")->setCurrentText("EquivalentStrain");
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  EXPECT_EQ(std::string(mapper->GetArrayName()), "EquivalentStrain");
  EXPECT_GT(mapper->GetScalarRange()[1], 0);
  EXPECT_LT(mapper->GetScalarRange()[1], 1);  // a strain, not a stress
}

// Compare: level 0 against level 2 over the wobble, shown on the surface;
// a frame chosen, the colouring switched, a vertex clicked for its error over
// time; the same level against itself has no error; Close brings the bound
// surface back.
TEST_F(Gui, ComparesTwoLevelsFrameByFrame) {
  openSample();
  child<QComboBox>("controlStyle")->setCurrentText("none");
  child<QComboBox>("solver")->setCurrentText("cg");  // (two runs alike, step for step)
  child<QSpinBox>("compareSteps")->setValue(20);
  EXPECT_EQ(child<QSpinBox>("compareReference")->value(), 2);
  EXPECT_EQ(child<QSpinBox>("compareLevel")->value(), 0);
  const auto before = window_->grabImage();
  QTest::mouseClick(child<QPushButton>("compare"), Qt::LeftButton);
  CompareDock& dock = *window_->compareDock();
  ASSERT_TRUE(dock.hasComparison()) << window_->lastError().toStdString();
  EXPECT_TRUE(window_->scene().comparisonShown());
  ASSERT_EQ(dock.frameCount(), 21u);
  const ComparedLevels& c = dock.compared();
  EXPECT_EQ(c.inspected, 0);
  EXPECT_EQ(c.reference, 2);
  EXPECT_GT(c.overall.distance.median, 0);
  EXPECT_TRUE(child<QLabel>("compareSummary")->text().contains("level 0"));
  dock.setFrame(20);
  EXPECT_TRUE(child<QLabel>("compareFrameText")->text().startsWith("frame 20 of 20"))
      << child<QLabel>("compareFrameText")->text().toStdString();
  const auto* histogram = dock.histogram();
  int total = 0;
  for (int n : histogram->counts()) total += n;
  EXPECT_EQ(total, 1839);
  EXPECT_DOUBLE_EQ(histogram->high(),
                   *std::max_element(c.distance[20].begin(), c.distance[20].end()));
  EXPECT_GT(changeFrom(before), 0.01);  // coloured by the error
  dock.setColouring("normal angle");
  EXPECT_DOUBLE_EQ(histogram->high(), *std::max_element(c.angle[20].begin(), c.angle[20].end()));

  const std::optional<Index> v =
      window_->clickAt(window_->view()->width() / 2, window_->view()->height() / 2);
  ASSERT_TRUE(v.has_value()) << "nothing under the centre of the view";
  EXPECT_EQ(dock.shownVertex(), v);
  ASSERT_EQ(dock.vertexPlot()->values().size(), 21u);
  for (std::size_t f = 0; f < 21; ++f)
    EXPECT_EQ(dock.vertexPlot()->values()[f], c.angle[f][static_cast<std::size_t>(*v)]);

  ASSERT_TRUE(window_->compareLevels(1, 1, 5)) << window_->lastError().toStdString();
  EXPECT_EQ(dock.compared().overall.distance.max, 0);
  EXPECT_EQ(dock.compared().overall.angle.max, 0);

  QTest::mouseClick(child<QPushButton>("compareClose"), Qt::LeftButton);
  EXPECT_FALSE(dock.hasComparison());
  EXPECT_FALSE(window_->scene().comparisonShown());
  EXPECT_TRUE(window_->scene().surfaceActor()->GetVisibility());
}

// A dataset whose texture file goes missing after it was opened: a rebind,
// another render path or another textured surface then cannot be drawn.
// Each says why and leaves the scene as it was, the old surface drawn.
TEST_F(Gui, AFailedRedrawKeepsTheSurfaceItHad) {
  const std::filesystem::path dir = scratch("textured");
  std::filesystem::create_directories(dir);
  const std::filesystem::path data = TETSKIN_SOURCE_DIR "/data";
  for (const char* name : {"bunny.node", "bunny.ele"})
    std::filesystem::copy_file(data / name, dir / name,
                               std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(data / "bunny_texture.png", dir / "tex.png",
                             std::filesystem::copy_options::overwrite_existing);
  std::stringstream config;
  config << std::ifstream(data / "bunny.json").rdbuf();
  std::string text = config.str();
  const std::string untextured = "\"texture\": null";
  ASSERT_NE(text.find(untextured), std::string::npos);
  text.replace(text.find(untextured), untextured.size(), "\"texture\": \"tex.png\"");
  std::ofstream(dir / "bunny.json") << text;
  std::ofstream(dir / "triangle.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                         "f 1/1 2/2 3/3\n";
  ASSERT_TRUE(window_->openFiles(
      {QString::fromStdString((dir / "bunny.json").string()), kData + "bunny_8k_tex.obj"}))
      << window_->lastError().toStdString();
  const Scene& scene = window_->scene();
  const Index vertices = scene.surface().vertexCount();
  const BindingMethod method = scene.binding().method;
  const int level = scene.level();
  const auto drawn = window_->grabImage();
  std::filesystem::remove(dir / "tex.png");

  child<QComboBox>("rebindMethod")->setCurrentText("seed");
  child<QSpinBox>("rebindLevel")->setValue(1);
  QTest::mouseClick(window_->findChild<QPushButton*>("rebind"), Qt::LeftButton);
  EXPECT_TRUE(window_->lastError().contains("tex.png")) << window_->lastError().toStdString();
  EXPECT_EQ(scene.binding().method, method);
  EXPECT_EQ(scene.level(), level);
  ASSERT_NE(scene.surfaceActor(), nullptr);
  EXPECT_LT(changeFrom(drawn), 0.001);

  window_->setRenderPath("gpu-1pass");
  EXPECT_EQ(scene.renderPath(), RenderPath::Cpu);
  EXPECT_EQ(child<QComboBox>("renderPath")->currentText(), "cpu");
  ASSERT_NE(scene.surfaceActor(), nullptr);
  EXPECT_LT(changeFrom(drawn), 0.001);

  EXPECT_FALSE(window_->openFile(QString::fromStdString((dir / "triangle.obj").string())));
  EXPECT_TRUE(window_->lastError().contains("tex.png")) << window_->lastError().toStdString();
  EXPECT_EQ(scene.surface().vertexCount(), vertices);
  EXPECT_EQ(scene.binding().vertexCount(), vertices);
  ASSERT_NE(scene.surfaceActor(), nullptr);
  EXPECT_LT(changeFrom(drawn), 0.001);

  // The dataset again (the surface would be bound to it anew): it cannot be
  // drawn either, so the scene keeps what it had on screen.
  EXPECT_FALSE(window_->openFile(QString::fromStdString((dir / "bunny.json").string())));
  EXPECT_TRUE(window_->lastError().contains("tex.png")) << window_->lastError().toStdString();
  ASSERT_NE(scene.surfaceActor(), nullptr);
  EXPECT_LT(changeFrom(drawn), 0.001);
}

// A dataset opens first, so that surfaces dropped with it bind to it; a
// frame opens last, so that a surface opened after it does not start the
// simulation again.
TEST_F(Gui, DroppedFilesOpenDatasetFirstAndFramesLast) {
  const auto drop = [&](const QList<QUrl>& urls) {
    QMimeData mime;
    mime.setUrls(urls);
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent event(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &event);
  };
  drop({QUrl::fromLocalFile(kData + "bunny_8k.obj"), QUrl::fromLocalFile(kData + "bunny.json")});
  ASSERT_TRUE(window_->scene().hasSurface())
      << window_->lastError().toStdString() << " / " << window_->windowTitle().toStdString();
  EXPECT_EQ(window_->scene().surface().triangleCount(), 7998);

  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  const std::filesystem::path frame = scratch("dropped.vtu");
  ASSERT_TRUE(window_->exportFrame(QString::fromStdString(frame.string())));
  const Points3 exported = window_->runner()->state().positions;
  QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  drop({QUrl::fromLocalFile(QString::fromStdString(frame.string())),
        QUrl::fromLocalFile(kData + "bunny.obj")});
  EXPECT_EQ(window_->scene().surface().vertexCount(), 1839) << window_->lastError().toStdString();
  EXPECT_EQ(window_->runner()->steps(), 0);
  EXPECT_EQ(window_->runner()->state().positions, exported);
}

TEST_F(Gui, BuildDialogBuildsADatasetAndCancels) {
  BuildDialog* dialog = window_->buildDialog();
  const std::filesystem::path out = scratch("built");
  std::filesystem::remove(scratch("built.json"));
  dialog->setInputs({kData + "bunny.obj"});
  dialog->setOutput(QString::fromStdString(out.string()));
  dialog->setLevels(1, 300, 3000);
  dialog->setQualities("2.0");
  ASSERT_TRUE(dialog->start());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->running(); }, 120000));
  EXPECT_TRUE(dialog->log().contains("done")) << dialog->log().toStdString();
  ASSERT_TRUE(window_->scene().hasDataset());
  EXPECT_EQ(window_->scene().datasetPath(), scratch("built.json"));
  // Cancel at once: no dataset is written.
  const std::filesystem::path other = scratch("cancelled");
  std::filesystem::remove(scratch("cancelled.json"));
  dialog->setOutput(QString::fromStdString(other.string()));
  dialog->setQualities("2.0,1.8,1.6,1.4,1.2");
  ASSERT_TRUE(dialog->start());
  dialog->cancel();
  EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->running(); }, 60000));
  EXPECT_TRUE(dialog->log().endsWith("cancelled")) << dialog->log().toStdString();
  EXPECT_FALSE(std::filesystem::exists(scratch("cancelled.json")));
}

// The dialog's sizing box reaches targets a box cannot meet by quality alone
// (6 elements at every quality), and its up axis reaches the config.
TEST_F(Gui, BuildDialogSizesABoxToItsTargets) {
  BuildDialog* dialog = window_->buildDialog();
  const std::filesystem::path out = scratch("sized_box");
  dialog->setInputs({QString(TETSKIN_SOURCE_DIR) + "/tests/data/cube_0.obj"});
  dialog->setOutput(QString::fromStdString(out.string()));
  dialog->setLevels(2, 300, 3000);
  dialog->setQualities("2.0,1.4");
  dialog->setSizeToTargets(true);
  dialog->findChild<QComboBox*>("up")->setCurrentText("z");  // reaches the config
  ASSERT_TRUE(dialog->start());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->running(); }, 120000));
  ASSERT_TRUE(window_->scene().hasDataset()) << dialog->log().toStdString();
  EXPECT_EQ(window_->scene().datasetPath(), scratch("sized_box.json"));
  const MultiLevelTetMesh& mesh = window_->scene().dataset().mesh;
  ASSERT_EQ(mesh.levelCount(), 2);
  EXPECT_NEAR(static_cast<double>(mesh.levels[0].elementCount), 300, 150);
  EXPECT_NEAR(static_cast<double>(mesh.levels[1].elementCount), 3000, 1500);
  EXPECT_FALSE(dialog->log().contains("warning")) << dialog->log().toStdString();
  EXPECT_EQ(window_->scene().dataset().config.up, UpAxis::Z);
}

// A scan with holes: the dialog wraps it (its default), shows what the wrap
// cost per level, and opens the dataset; with the wrap off it is refused.
TEST_F(Gui, BuildDialogWrapsAHoledScanAndShowsTheWrapsFidelity) {
  BuildDialog* dialog = window_->buildDialog();
  dialog->setInputs({QString(TETSKIN_SOURCE_DIR) + "/tests/data/bunny_holed.obj"});
  dialog->setOutput(QString::fromStdString(scratch("refused_holed").string()));
  dialog->setLevels(1, 3000, 3000);
  dialog->setQualities("2.0");
  dialog->setWrap("never", 0.02, 0.002);
  ASSERT_TRUE(dialog->start());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->running(); }, 120000));
  EXPECT_TRUE(dialog->log().contains("cannot be repaired")) << dialog->log().toStdString();
  EXPECT_TRUE(dialog->wrapFidelity().isEmpty());

  dialog->setOutput(QString::fromStdString(scratch("wrapped_holed").string()));
  dialog->setWrap("auto", 0.02, 0.002);
  ASSERT_TRUE(dialog->start());
  EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->running(); }, 120000));
  ASSERT_TRUE(window_->scene().hasDataset()) << dialog->log().toStdString();
  EXPECT_EQ(window_->scene().datasetPath(), scratch("wrapped_holed.json"));
  EXPECT_TRUE(dialog->log().contains("wrapped ")) << dialog->log().toStdString();
  EXPECT_TRUE(dialog->wrapFidelity().startsWith("Level 0 against the input: input -> level: mean "))
      << dialog->wrapFidelity().toStdString();
  EXPECT_TRUE(
      dialog->wrapFidelity().contains("Level 0 was meshed from a wrap: alpha 2% and "
                                      "offset 0.2% of the diagonal"))
      << dialog->wrapFidelity().toStdString();
  ASSERT_TRUE(window_->scene().dataset().config.levels[0].fidelity.has_value());
  EXPECT_TRUE(window_->scene().dataset().config.levels[0].fidelity->faithful);
  EXPECT_FALSE(dialog->findChild<QLabel*>("wrapFidelity")->isHidden());
  ASSERT_TRUE(window_->scene().dataset().config.levels[0].source.wrap.has_value());
}

TEST_F(Gui, ScreenshotMatchesItsBaseline) {
  openSample();
  const std::filesystem::path png = scratch("screenshot.png");
  ASSERT_TRUE(window_->saveScreenshot(QString::fromStdString(png.string())));
  test::expectMatchesBaseline(readPng(png), TETSKIN_BASELINE_DIR, TETSKIN_ACTUAL_DIR,
                              "gui_sample.png", 0.005);
}

}  // namespace
}  // namespace tetskin::gui
