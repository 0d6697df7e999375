// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// tetskin-gui's command line:
//   tetskin-gui [DATASET.json] [SURFACE] [--screenshot FILE [--window]] [--path PATH]
//               [--size WxH] [--camera PRESET] [--control STYLE] [--color-by ARRAY]
//               [--highlight] [--prescribed] [--pick] [--scenario NAME] [--steps N]
//               [--no-overlay] [--compare LEVEL] [--print-run]
// declared once (GuiArguments), read before a display is needed (help,
// version and usage errors work over ssh), and applied to the window the
// way a user would set its docks (applyArguments): each option sets a
// dock's widget and presses its button, so the docks show what runs.

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <optional>

#include "Scene.h"
#include "tetskin/core/OptionSchema.h"
#include "tetskin/rendering/ControlMeshActor.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/rendering/RenderPath.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/simulation/Scenario.h"

namespace tetskin::gui {

class MainWindow;

// "a, b or c": the names a choice offers (OptionSchema.h).
template <SchemaEnum E>
QString choices() {
  return QString::fromStdString(oneOf(namesOf<E>()));
}

// The command line: declared once, read before a display is needed (help,
// version and usage errors work over ssh), and again once the QApplication
// has taken its own options (-platform, -style, ...) out.
struct GuiArguments {
  QCommandLineParser parser;
  QCommandLineOption screenshot{"screenshot", "render one frame to FILE (PNG) and exit", "FILE"};
  QCommandLineOption path{tetskin::kRenderPathOption.key, choices<tetskin::RenderPath>(), "PATH",
                          tetskin::toString(tetskin::kDefaultRenderPath)};
  QCommandLineOption size{"size",
                          "with --screenshot the image's size (the view's, or with --window "
                          "the window's), else the window's: WIDTHxHEIGHT",
                          "WxH", "1280x800"};
  QCommandLineOption camera{tetskin::kCameraOption.key, choices<tetskin::CameraPreset>(), "PRESET",
                            tetskin::toString(tetskin::kDefaultCamera)};
  QCommandLineOption whole{"window", "with --screenshot: the whole window, docks included"};
  QCommandLineOption control{
      tetskin::kControlMeshOption.key,
      tetskin::kControlMeshOption.help + choices<tetskin::ControlMeshStyle>(), "STYLE"};
  QCommandLineOption colorBy{"color-by", choices<tetskin::gui::ColorBy>(), "ARRAY"};
  QCommandLineOption highlight{"highlight", "mark vertices with negative weights or far"};
  QCommandLineOption prescribed{"prescribed",
                                "mark the nodes the simulation holds still or drives"};
  QCommandLineOption pick{"pick", "inspect the vertex at the centre of the view"};
  QCommandLineOption scenario{tetskin::kScenarioOption.key,
                              QString::fromStdString(tetskin::kScenarioOption.help +
                                                     tetskin::oneOf(tetskin::scenarioNames())) +
                                  " (the Simulation dock's)",
                              "NAME"};
  QCommandLineOption steps{
      tetskin::recording_option::kSteps.key,
      QString("simulate N steps first; with --compare, compare over N steps (default: the "
              "Compare dock's, %1)")
          .arg(tetskin::recording_option::kSteps.defaultValue),
      "N", "0"};
  QCommandLineOption noOverlay{"no-overlay", "hide the frame statistics (View > Frame statistics)"};
  QCommandLineOption compare{"compare",
                             "compare LEVEL with the finest over --steps steps instead of "
                             "simulating them (the Compare dock), showing the last frame",
                             "LEVEL"};
  QCommandLineOption printRun{"print-run",
                              "print the run the Simulation dock describes (JSON, as tetskin "
                              "simulate --print-run) and exit"};
  // Checked values.
  int width = 0, height = 0, stepCount = 0, compareLevel = 0;

  GuiArguments();
  // Parses the application's arguments; prints help or the version and
  // exits, or checks the values. false (after one line `error: ...`) on a
  // usage error.
  bool read(const QCoreApplication& app) { return read(app.arguments()); }
  // The same from `arguments` (the program's name first).
  bool read(const QStringList& arguments);
};

// Opens the files the arguments name and sets the docks as they say, then
// takes the screenshot (--screenshot) or prints the run (--print-run).
// nullopt: carry on (the event loop); else the exit status, after one line
// `error: ...` on stderr for a failure.
std::optional<int> applyArguments(const GuiArguments& args, MainWindow& window);

}  // namespace tetskin::gui
