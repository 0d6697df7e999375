// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui's command line (CommandLine.h) applied to the window: every
// option goes through the docks, so that they show what runs.
#include "CommandLine.h"
#include "GuiFixture.h"

namespace tetskin::gui {
namespace {

// The arguments as tetskin-gui would read them, checked.
std::unique_ptr<GuiArguments> arguments(const QStringList& given) {
  auto args = std::make_unique<GuiArguments>();
  EXPECT_TRUE(args->read(QStringList{"tetskin-gui"} + given));
  return args;
}

TEST_F(Gui, TheCommandLinesComparisonIsTheCompareDocksOwn) {
  const auto args =
      arguments({kData + "bunny.json", kData + "bunny.obj", "--compare", "0", "--steps", "6"});
  EXPECT_EQ(applyArguments(*args, *window_), std::nullopt) << window_->lastError().toStdString();
  // The dock shows the levels and steps that ran, on its last frame.
  EXPECT_EQ(child<QSpinBox>("compareSteps")->value(), 6);
  EXPECT_EQ(child<QSpinBox>("compareLevel")->value(), 0);
  EXPECT_EQ(child<QSpinBox>("compareReference")->value(), 2);
  CompareDock& dock = *window_->compareDock();
  ASSERT_TRUE(dock.hasComparison());
  EXPECT_EQ(dock.frameCount(), 7u);
  EXPECT_EQ(dock.frame(), 6);
  EXPECT_EQ(dock.compared().inspected, 0);
  EXPECT_EQ(dock.compared().reference, 2);
}

TEST_F(Gui, TheCommandLinesScenarioAndStepsAreTheSimulationDocks) {
  const auto args = arguments({kData + "bunny.json", "--scenario", "sag", "--steps", "3"});
  EXPECT_EQ(applyArguments(*args, *window_), std::nullopt) << window_->lastError().toStdString();
  EXPECT_EQ(child<QComboBox>("scenario")->currentText(), "sag");
  ASSERT_NE(window_->runner(), nullptr);
  EXPECT_STREQ(window_->runner()->session().scenario().name(), "sag");
  EXPECT_EQ(window_->runner()->steps(), 3);
}

TEST_F(Gui, ACommandLineValueTheDockDoesNotOfferIsAnError) {
  const auto args = arguments({kData + "bunny.json", "--scenario", "fly"});
  EXPECT_EQ(applyArguments(*args, *window_), 1);
  GuiArguments bad;
  EXPECT_FALSE(bad.read({"tetskin-gui", "--steps", "-1"}));
}

}  // namespace
}  // namespace tetskin::gui
