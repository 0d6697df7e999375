// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: the Simulation dock's fields: material, solver, scenario
// parameters, held nodes and box, up axis, what the next run is made of.
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

// The Simulation dock starts from the dataset's elasticity section (the
// defaults where it has no value); the simulation takes the dock's material;
// a surface opened afterwards leaves the dock as the user set it.
TEST_F(Gui, SimulationTakesTheDatasetsMaterial) {
  const QString stiff = QString(TETSKIN_SOURCE_DIR) + "/tests/data/stiff_bunny.json";
  ASSERT_TRUE(window_->openFiles({stiff})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("youngs_modulus")->value(), 2e6);
  EXPECT_EQ(child<QDoubleSpinBox>("density")->value(), 50.0);
  EXPECT_EQ(child<QDoubleSpinBox>("mass_damping")->value(), ElasticMaterial{}.massDamping);
  EXPECT_EQ(child<QDoubleSpinBox>("stiffness_damping")->value(),
            ElasticMaterial{}.stiffnessDamping);
  ASSERT_NE(window_->runner(), nullptr);
  auto material = [&] { return window_->runner()->simulation().options().material; };
  EXPECT_EQ(material().youngsModulus, 2e6);
  EXPECT_EQ(material().density, 50.0);
  child<QDoubleSpinBox>("youngs_modulus")->setValue(7e5);
  child<QDoubleSpinBox>("poisson_ratio")->setValue(0.4999);
  child<QDoubleSpinBox>("density")->setValue(1200);
  child<QDoubleSpinBox>("mass_damping")->setValue(0.5);
  child<QDoubleSpinBox>("stiffness_damping")->setValue(0.002);
  ASSERT_TRUE(window_->openFiles({kData + "bunny_8k.obj"})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("youngs_modulus")->value(), 7e5);
  EXPECT_EQ(material().youngsModulus, 7e5);
  EXPECT_EQ(material().poissonRatio, 0.4999);
  EXPECT_EQ(material().density, 1200.0);
  EXPECT_EQ(material().massDamping, 0.5);
  EXPECT_EQ(material().stiffnessDamping, 0.002);
  ASSERT_TRUE(window_->openFiles({kData + "bunny.json"})) << window_->lastError().toStdString();
  EXPECT_EQ(child<QDoubleSpinBox>("youngs_modulus")->value(), 2e5);
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
  EXPECT_EQ(type("time_step", "2.5e-5"), 2.5e-5);
  EXPECT_EQ(type("youngs_modulus", "5E13"), 5e13);
  EXPECT_EQ(type("poisson_ratio", "0.49995"), 0.49995);
  EXPECT_EQ(type("stiffness_damping", "1e-7"), 1e-7);
  EXPECT_EQ(type("density", "x"), ElasticMaterial{}.density);  // refused: unchanged
  EXPECT_EQ(type("poisson_ratio", "0.5"), 0.49995);            // out of (-1, 0.5): unchanged
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
  child<QDoubleSpinBox>("tolerance")->setValue(1e-3);
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
  EXPECT_EQ(window_->runner()->simulation().fixedNodes(),
            fixedWithNodesInBox({0, 1, 2}, rest, box));
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

}  // namespace
}  // namespace tetskin::gui
