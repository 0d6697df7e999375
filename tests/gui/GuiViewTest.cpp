// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: the View dock and the view: toggles, render paths, the frame
// statistics, the docks' fit, and a screenshot against its baseline.
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

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

TEST_F(Gui, ScreenshotMatchesItsBaseline) {
  openSample();
  const std::filesystem::path png = scratch("screenshot.png");
  ASSERT_TRUE(window_->saveScreenshot(QString::fromStdString(png.string())));
  test::expectMatchesBaseline(readPng(png), TETSKIN_BASELINE_DIR, TETSKIN_ACTUAL_DIR,
                              "gui_sample.png", 0.005);
}

}  // namespace
}  // namespace tetskin::gui
