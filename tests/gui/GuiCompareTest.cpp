// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui driven as a user would: the Compare dock and the comparison of levels
// (ComparisonController).
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

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

}  // namespace
}  // namespace tetskin::gui
