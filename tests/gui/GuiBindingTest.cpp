// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: the Binding dock: picking a vertex, the diagnostics,
// rebinding.
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

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

}  // namespace
}  // namespace tetskin::gui
