// SPDX-License-Identifier: AGPL-3.0-or-later
// Scenes in tetskin-gui: a scene file opens its placed body, skin and
// obstacles (drawn translucent) and runs the scene's run; the skin is
// coloured by its contact and the picked vertex shows its contact state;
// the contacts per step are plotted; obstacles are added from a file and
// placed (the box widget's end, made uniform); a recording carries the
// obstacles.
#include <vtkBoxRepresentation.h>
#include <vtkBoxWidget2.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkTransform.h>

#include <fstream>

#include "GuiFixture.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/session/RunSpecJson.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/vtkio/RunRecorder.h"

namespace tetskin::gui {
namespace {

const QString kBowlScene = kData + "scenes/bunny-in-bowl.json";

class GuiScene : public Gui {
 protected:
  void openBowlScene() {
    ASSERT_TRUE(window_->openFile(kBowlScene)) << window_->lastError().toStdString();
    ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  }
  void step(int n) {
    for (int i = 0; i < n; ++i) QTest::mouseClick(child<QPushButton>("step"), Qt::LeftButton);
  }
};

TEST_F(GuiScene, OpensTheSceneAndRunsItsRun) {
  openBowlScene();
  const SceneRun run = loadScene(readScene(kBowlScene.toStdString()));
  Scene& scene = window_->scene();
  // The body as the scene places it, its skin bound to the scene's level.
  EXPECT_EQ(scene.dataset().mesh.nodes, run.dataset.mesh.nodes);
  ASSERT_TRUE(scene.hasSurface());
  EXPECT_EQ(scene.surface().positions, run.surface->surface.positions);
  EXPECT_EQ(scene.level(), run.level);
  // The bowl drawn translucent, framed with the body.
  ASSERT_EQ(scene.obstacles().size(), 1u);
  vtkActor* bowl = scene.obstacleActor(0).actor();
  EXPECT_TRUE(window_->renderer()->GetActors()->IsItemPresent(bowl));
  EXPECT_LT(bowl->GetProperty()->GetOpacity(), 1);
  // The dock's run is the scene's (as simulate and Python resolve it).
  EXPECT_EQ(child<QComboBox>("scenario")->currentText(), "free");
  EXPECT_EQ(runSpecJson(window_->simulationDock()->runSpec()),
            runSpecJson(resolveRun(run.request, run.dataset.mesh, run.dataset.config)));
  EXPECT_EQ(window_->runner()->simulation().options().obstacles.size(), 1u);
  // A dataset opened after it: no obstacles, the dataset's own run.
  openSample();
  EXPECT_TRUE(window_->scene().obstacles().empty());
  EXPECT_TRUE(window_->runner()->simulation().options().obstacles.empty());
  EXPECT_EQ(child<QComboBox>("scenario")->currentText(), "free");  // (the rows as left)
}

// A scene of several bodies: one dataset of their levels, one skin of
// their skins, the run the scene's (each body's material and start); a
// vertex of the second body is bound to that body's nodes, and the second
// body, dropped onto the first, meets its skin.
TEST_F(GuiScene, OpensASceneOfSeveralBodiesAndRunsThemAsOne) {
  const QString path = QString(TETSKIN_SOURCE_DIR) + "/tests/data/scenes/two_bunnies.json";
  ASSERT_TRUE(window_->openFile(path)) << window_->lastError().toStdString();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const SceneRun run = loadScene(readScene(path.toStdString()));
  ASSERT_EQ(run.request.bodies.size(), 2u);
  Scene& scene = window_->scene();
  EXPECT_EQ(scene.dataset().mesh.nodes, run.dataset.mesh.nodes);
  ASSERT_TRUE(scene.hasSurface());
  EXPECT_EQ(scene.surface().vertexCount(), run.surface->surface.vertexCount());
  EXPECT_EQ(runSpecJson(window_->simulationDock()->runSpec()),
            runSpecJson(resolveRun(run.request, run.dataset.mesh, run.dataset.config)));
  const BodyRange& second = run.request.bodies[1].range;
  const VertexInfo info = scene.vertexInfo(second.firstVertex + 10);
  for (int j = 0; j < 3; ++j) {
    EXPECT_GE(info.controlIds[j], second.firstNode);
    EXPECT_LT(info.controlIds[j], second.firstNode + second.nodeCount);
  }
  SimulationRunner& runner = *window_->runner();
  EXPECT_GT(runner.simulation().skinThickness(), 0);
  for (int i = 0; i < 60 && runner.lastStats().contacts == 0; ++i) step(1);
  EXPECT_GT(runner.lastStats().contacts, 0) << "the second bunny lands on the first";
}

// Skins meet each other without a floor or obstacles too: the GUI binds
// the skin into a run of several bodies whatever else it has.
TEST_F(GuiScene, BindsTheSkinsOfSeveralBodiesWithoutAFloor) {
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const std::filesystem::path path = scratch("two_bodies_no_floor.json");
  {
    std::ofstream out(path);
    out << R"({"format": "tetskin-scene", "version": 1, "gravity": [0, 0, 0], "bodies": [)"
        << R"({"dataset": ")" << data << R"(bunny.json", "level": 0}, )"
        << R"({"dataset": ")" << data << R"(bunny.json", "level": 0, "translate": [30, 0, 0]}]})";
  }
  ASSERT_TRUE(window_->openFile(QString::fromStdString(path.string())))
      << window_->lastError().toStdString();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  EXPECT_FALSE(window_->runner()->simulation().options().hasContact());
  EXPECT_GT(window_->runner()->simulation().skinThickness(), 0);
}

// Any body of a scene can be pulled: shift-dragging the second bunny's
// highest skin vertex picks that vertex and pulls its own nodes, none of
// the first bunny's.
TEST_F(GuiScene, PullsTheSecondBodyOfAScene) {
  const QString path = QString(TETSKIN_SOURCE_DIR) + "/tests/data/scenes/two_bunnies.json";
  ASSERT_TRUE(window_->openFile(path)) << window_->lastError().toStdString();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const SceneRun run = loadScene(readScene(path.toStdString()));
  const BodyRange& second = run.request.bodies[1].range;
  window_->grabImage();
  Scene& scene = window_->scene();
  Index top = second.firstVertex;
  for (Index v = second.firstVertex; v < second.firstVertex + second.vertexCount; ++v)
    if (scene.surface().positions(v, 1) > scene.surface().positions(top, 1)) top = v;
  const Eigen::Vector2d at = project(scene.vertexInfo(top).position);
  QWidget* view = window_->view();
  const QPoint from(static_cast<int>(at.x()), view->height() - 1 - static_cast<int>(at.y()));
  mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::ShiftModifier);
  const std::optional<Index> grabbed = scene.pickedVertex();
  ASSERT_TRUE(grabbed.has_value());
  EXPECT_GE(*grabbed, second.firstVertex);
  EXPECT_LT(*grabbed, second.firstVertex + second.vertexCount);
  mouse(QEvent::MouseMove, from + QPoint(60, 0), Qt::LeftButton, Qt::ShiftModifier);
  SimulationRunner& runner = *window_->runner();
  const Index start = runner.steps();
  EXPECT_TRUE(QTest::qWaitFor([&] { return runner.steps() >= start + 3; }, 30000));
  const Points3 pulled = runner.simulation().externalForces();
  mouse(QEvent::MouseButtonRelease, from + QPoint(60, 0), Qt::NoButton, Qt::ShiftModifier);
  EXPECT_GT(pulled.middleRows(second.firstNode, second.nodeCount).norm(), 0);
  EXPECT_EQ(pulled.topRows(second.firstNode).norm(), 0);
}

// A run of several bodies, recorded from their scene, replays on the
// scene: each frame the bodies' frames side by side; Continue starts the
// scene from the frame shown. Opened alone, it asks for its scene.
TEST_F(GuiScene, ReplaysARunOfSeveralBodiesAndContinuesFromIt) {
  const QString path = QString(TETSKIN_SOURCE_DIR) + "/tests/data/scenes/two_bunnies.json";
  ASSERT_TRUE(window_->openFile(path)) << window_->lastError().toStdString();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  const std::filesystem::path pvd = scratch("two_bodies.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  std::vector<Points3> states{window_->runner()->state().positions};
  for (int i = 0; i < 2; ++i) {
    step(1);
    states.push_back(window_->runner()->state().positions);
  }
  window_->stopRecording();
  QTest::mouseClick(child<QPushButton>("reset"), Qt::LeftButton);
  ASSERT_TRUE(window_->openFile(QString::fromStdString(pvd.string())))
      << window_->lastError().toStdString();
  auto* slider = child<QSlider>("runFrame");
  EXPECT_EQ(slider->maximum(), 2);
  slider->setValue(2);
  EXPECT_EQ(window_->scene().controlNodes(), states[2]);
  // A frame of several bodies is no one frame file to export.
  EXPECT_FALSE(window_->exportFrame(QString::fromStdString(scratch("two.vtu").string())));
  EXPECT_NE(window_->lastError().indexOf("keeps a frame file per body"), -1)
      << window_->lastError().toStdString();
  QTest::mouseClick(child<QPushButton>("runContinue"), Qt::LeftButton);
  EXPECT_EQ(window_->runner()->state().positions, states[2]);
  EXPECT_EQ(window_->runner()->steps(), 0);
  step(1);
  EXPECT_NE(window_->runner()->state().positions, states[2]);

  window_ = std::make_unique<MainWindow>(false);
  EXPECT_FALSE(window_->openFile(QString::fromStdString(pvd.string())));
  EXPECT_EQ(window_->lastError().toStdString(),
            pvd.string() + ": records a scene of 2 bodies: open the scene first");
}

// A scene's pressure on the bunny's upper half: arrows at the loaded nodes
// (none elsewhere), and none once a run without surface loads is open.
TEST_F(GuiScene, DrawsTheSurfaceLoadsAsArrows) {
  const QString path = QString(TETSKIN_SOURCE_DIR) + "/tests/data/scenes/pressed_bunny.json";
  ASSERT_TRUE(window_->openFile(path)) << window_->lastError().toStdString();
  ASSERT_NE(window_->runner(), nullptr) << window_->lastError().toStdString();
  step(2);
  SimulationRunner& runner = *window_->runner();
  const Points3 forces = runner.simulation().surfaceLoadForces(runner.state());
  const Index loaded = (forces.rowwise().squaredNorm().array() > 0).count();
  ASSERT_GT(loaded, 0);
  Scene& scene = window_->scene();
  EXPECT_EQ(scene.loadArrowCount(), loaded);
  EXPECT_LT(loaded, forces.rows());  // the upper half's nodes only
  // The pressure pushes the top down overall.
  EXPECT_LT(forces.col(1).sum(), 0);
  // The energy plot shows the loads' potential, in its total too.
  auto* plot = child<EnergyPlot>("energyPlot");
  ASSERT_FALSE(plot->samples().empty());
  const Energies now = runner.simulation().energies();
  EXPECT_EQ(plot->samples().back().load, now.load);
  EXPECT_NE(now.load, 0);
  EXPECT_EQ(plot->legend().size(), 5);
  EXPECT_TRUE(plot->legend()[3].startsWith("load "));
  ASSERT_TRUE(window_->openFile(kBowlScene)) << window_->lastError().toStdString();
  step(1);
  EXPECT_EQ(window_->scene().loadArrowCount(), 0);
}

TEST_F(GuiScene, ColoursTheSkinByItsContactAndPlotsTheContacts) {
  openBowlScene();
  child<QSpinBox>("controlLevel");  // (exists; the level stays the scene's)
  EXPECT_TRUE(child<SeriesPlot>("contactPlot")->isHidden());
  SimulationRunner& runner = *window_->runner();
  for (int i = 0; i < 150 && runner.lastStats().contacts == 0; ++i) step(1);  // it falls
  step(5);  // and lands in the bowl
  const SkinContact contact = runner.simulation().skinContact(runner.state());
  ASSERT_EQ(contact.penetration.size(), window_->scene().surface().vertexCount());
  Index deepest = 0;
  contact.penetration.maxCoeff(&deepest);
  ASSERT_GT(contact.penetration[deepest], 0) << "the skin touches the bowl";
  // The contacts of the steps, plotted.
  SeriesPlot* plot = child<SeriesPlot>("contactPlot");
  EXPECT_FALSE(plot->isHidden());
  ASSERT_FALSE(plot->values().empty());
  EXPECT_EQ(plot->values().back(), runner.lastStats().contacts);
  EXPECT_GT(plot->values().back(), 0);
  // Coloured by penetration: the drawn array is the run's.
  child<QComboBox>("colorBy")->setCurrentText("Penetration");
  vtkDataArray* drawn =
      window_->scene().deformable()->polyData()->GetPointData()->GetArray("Penetration");
  ASSERT_NE(drawn, nullptr);
  ASSERT_EQ(drawn->GetNumberOfTuples(), contact.penetration.size());
  EXPECT_DOUBLE_EQ(drawn->GetTuple1(deepest), contact.penetration[deepest]);
  child<QComboBox>("colorBy")->setCurrentText("ContactForce");
  drawn = window_->scene().deformable()->polyData()->GetPointData()->GetArray("ContactForce");
  ASSERT_NE(drawn, nullptr);
  EXPECT_NEAR(drawn->GetTuple1(deepest), contact.forces.row(deepest).norm(),
              1e-9 * contact.forces.row(deepest).norm());
  // The picked vertex's contact state.
  child<QComboBox>("colorBy")->setCurrentText("material");
  window_->scene().showPickedVertex(deepest);
  window_->run().refreshSkinContact();
  const VertexInfo info = window_->scene().vertexInfo(deepest);
  ASSERT_TRUE(info.penetration.has_value());
  EXPECT_DOUBLE_EQ(*info.penetration, contact.penetration[deepest]);
  EXPECT_TRUE(window_->vertexInfoText().contains("in contact"))
      << window_->vertexInfoText().toStdString();
}

TEST_F(GuiScene, RecordsTheObstaclesWithTheRun) {
  openBowlScene();
  const std::filesystem::path pvd = scratch("scene_run.pvd");
  ASSERT_TRUE(window_->startRecording(QString::fromStdString(pvd.string())));
  step(3);
  window_->stopRecording();
  const PvdSeries series = PvdSeries::read(pvd);
  int obstacleFrames = 0, surfaceFrames = 0;
  for (const PvdSeries::Entry& e : series.entries()) {
    if (e.part == RunRecorder::kFirstObstaclePart) ++obstacleFrames;
    if (e.part == 1) ++surfaceFrames;
  }
  EXPECT_GT(surfaceFrames, 0);
  EXPECT_EQ(obstacleFrames, surfaceFrames);
  const auto skin = readVtp(pvd.parent_path() / series.framesOfPart(1).back().file);
  EXPECT_NE(skin->GetPointData()->GetArray("Penetration"), nullptr);
}

TEST_F(GuiScene, AddsAnObstacleFromAFileAndRefusesAnOpenOne) {
  openSample();
  const QString bowl = kData + "scenes/bowl.obj";
  ASSERT_TRUE(window_->addObstacle(bowl)) << window_->lastError().toStdString();
  ASSERT_EQ(window_->scene().obstacles().size(), 1u);
  ASSERT_NE(window_->runner(), nullptr);
  EXPECT_EQ(window_->runner()->simulation().options().obstacles.size(), 1u);
  const QString open = QString(TETSKIN_SOURCE_DIR) + "/tests/data/open_sheet.obj";
  EXPECT_FALSE(window_->addObstacle(open));
  EXPECT_TRUE(window_->lastError().contains("open_sheet.obj"))
      << window_->lastError().toStdString();
  EXPECT_EQ(window_->scene().obstacles().size(), 1u);
}

// The box widget's transform, made one scale: the rotation nearest its
// linear part and the scale of the same volume.
TEST(ObstacleBoxPose, IsTheTransformWithAUniformScale) {
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(1, 2, 3);
  transform->RotateWXYZ(30, 0, 0, 1);
  transform->Scale(2, 2, 2);
  ObstaclePose pose = poseOfBoxTransform(transform);
  EXPECT_NEAR((pose.translation - Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_NEAR(pose.scale, 2, 1e-12);
  EXPECT_NEAR(pose.rotation.angularDistance(
                  Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()))),
              0, 1e-9);
  transform->Scale(1, 1, 8);  // a box pulled along one side: the same volume's cube
  pose = poseOfBoxTransform(transform);
  EXPECT_NEAR(pose.scale, 4, 1e-12);  // (2 * 2 * 16)^(1/3)
  EXPECT_NEAR(pose.rotation.angularDistance(
                  Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()))),
              0, 1e-9);
}

TEST_F(GuiScene, PlacesAnObstacleWithTheBoxWhilePaused) {
  openBowlScene();
  step(2);
  ASSERT_TRUE(window_->showObstacleBox(0));
  ObstacleBox& box = window_->obstacleBox();
  EXPECT_EQ(box.shownObstacle(), std::optional<std::size_t>(0));
  EXPECT_TRUE(box.widget()->GetEnabled());
  // A user's drag: the box moved 1 up and pulled to twice its size along x.
  auto* representation = vtkBoxRepresentation::SafeDownCast(box.widget()->GetRepresentation());
  auto dragged = vtkSmartPointer<vtkTransform>::New();
  dragged->Translate(0, 1, 0);
  dragged->Scale(2, 1, 1);
  representation->SetTransform(dragged);
  box.finishInteraction();
  const ObstaclePose placed = window_->scene().obstacles()[0].placement;
  EXPECT_NEAR((placed.translation - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR(placed.scale, std::cbrt(2.0), 1e-9);
  // The paused run meets it there from its next step, without a reset.
  EXPECT_EQ(window_->runner()->steps(), 2);
  EXPECT_NEAR(window_->runner()->simulation().options().obstacles[0].placement.scale,
              std::cbrt(2.0), 1e-9);
  // The box shows the placement made uniform.
  auto shown = vtkSmartPointer<vtkTransform>::New();
  representation->GetTransform(shown);
  EXPECT_NEAR(poseOfBoxTransform(shown).scale, std::cbrt(2.0), 1e-9);
  EXPECT_NEAR(shown->GetMatrix()->GetElement(0, 0), std::cbrt(2.0), 1e-9);
  ASSERT_TRUE(window_->showObstacleBox(std::nullopt));
  EXPECT_FALSE(box.widget()->GetEnabled());
  EXPECT_FALSE(window_->showObstacleBox(3));
}

}  // namespace
}  // namespace tetskin::gui
