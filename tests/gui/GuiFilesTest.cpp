// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: opening files (datasets, surfaces, bindings, meshes, drops),
// their errors, and the Build dialog.
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

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

}  // namespace
}  // namespace tetskin::gui
