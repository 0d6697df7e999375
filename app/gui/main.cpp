// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui [DATASET.json] [SURFACE] [--screenshot FILE [--window]] [--path PATH]
//             [--size WxH] [--camera PRESET] [--control STYLE] [--color-by ARRAY]
//             [--highlight] [--pick] [--steps N]
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCommandLineParser>
#include <QPushButton>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstdlib>

#include "MainWindow.h"

int main(int argc, char** argv) {
  const char* display = std::getenv("DISPLAY");
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  if ((!display || !*display) && !platform) {
    std::fprintf(stderr,
                 "error: tetskin-gui needs an X display (no DISPLAY is set; for --screenshot "
                 "run under xvfb-run -a)\n");
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TetSkin");
  QApplication::setApplicationName("tetskin-gui");
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "TetSkin: inspect how a surface is bound to a simulated tetrahedral control mesh");
  parser.addHelpOption();
  parser.addPositionalArgument("DATASET", "dataset (.json, or a .node/.ele pair)", "[DATASET]");
  parser.addPositionalArgument("SURFACE", "surface to bind (.obj .ply .stl .vtp)", "[SURFACE]");
  const QCommandLineOption screenshot("screenshot", "render one frame to FILE (PNG) and exit",
                                      "FILE");
  const QCommandLineOption path("path", "cpu, gpu-1pass, gpu-2pass, fur-cpu or fur-gpu", "PATH",
                                "cpu");
  const QCommandLineOption size("size", "window size WIDTHxHEIGHT", "WxH", "1280x800");
  const QCommandLineOption camera("camera", "iso, front, side or top", "PRESET", "iso");
  const QCommandLineOption whole("window", "with --screenshot: the whole window, docks included");
  const QCommandLineOption control("control", "control mesh: none, surface, wireframe, shrink",
                                   "STYLE");
  const QCommandLineOption colorBy("color-by", "material, MinBarycentric, Distance or FaceId",
                                   "ARRAY");
  const QCommandLineOption highlight("highlight", "mark vertices with negative weights or far");
  const QCommandLineOption pick("pick", "inspect the vertex at the centre of the view");
  const QCommandLineOption steps("steps", "simulate N steps first", "N", "0");
  parser.addOptions(
      {screenshot, whole, path, size, camera, control, colorBy, highlight, pick, steps});
  parser.process(app);

  int width = 1280, height = 800;
  if (std::sscanf(parser.value(size).toStdString().c_str(), "%dx%d", &width, &height) != 2 ||
      width < 64 || height < 64) {
    std::fprintf(stderr, "error: --size must be WIDTHxHEIGHT, got '%s'\n",
                 parser.value(size).toStdString().c_str());
    return 1;
  }
  const bool oneShot = parser.isSet(screenshot);
  tetskin::gui::MainWindow window(!oneShot);
  window.resize(width, height);
  window.show();
  QApplication::processEvents();
  const auto fail = [&window] {
    std::fprintf(stderr, "error: %s\n", window.lastError().toStdString().c_str());
    return 1;
  };
  if (!window.openFiles(parser.positionalArguments()) && oneShot) return fail();
  if (parser.isSet(path)) {
    window.setRenderPath(parser.value(path));
    if (!window.lastError().isEmpty() && oneShot) return fail();
  }
  // Settings as a user would make them in the docks.
  const auto choose = [&window](const char* box, const QString& value) {
    auto* combo = window.findChild<QComboBox*>(box);
    if (combo->findText(value) < 0) {
      std::fprintf(stderr, "error: '%s' is not one of the %s choices\n",
                   value.toStdString().c_str(), box);
      return false;
    }
    combo->setCurrentText(value);
    return true;
  };
  if (parser.isSet(camera) && !choose("camera", parser.value(camera))) return 1;
  if (parser.isSet(control) && !choose("controlStyle", parser.value(control))) return 1;
  if (parser.isSet(colorBy) && !choose("colorBy", parser.value(colorBy))) return 1;
  if (parser.isSet(highlight)) window.findChild<QCheckBox*>("highlight")->setChecked(true);
  bool stepsOk = false;
  const int stepCount = parser.value(steps).toInt(&stepsOk);
  if (!stepsOk || stepCount < 0) {
    std::fprintf(stderr, "error: --steps must be a whole number >= 0, got '%s'\n",
                 parser.value(steps).toStdString().c_str());
    return 1;
  }
  for (int i = 0; i < stepCount; ++i) window.findChild<QPushButton*>("step")->click();
  // Steps asked for but not taken (the simulation could not start: its
  // error is the window's last) must not pass for a simulated screenshot.
  if (oneShot && stepCount > 0 && !window.lastError().isEmpty()) return fail();
  if (parser.isSet(pick)) {
    window.renderNow();
    window.clickAt(window.view()->width() / 2, window.view()->height() / 2);
  }
  if (oneShot) {
    QApplication::processEvents();
    if (!window.saveScreenshot(parser.value(screenshot), parser.isSet(whole))) return fail();
    std::printf("wrote %s\n", parser.value(screenshot).toStdString().c_str());
    return 0;
  }
  return QApplication::exec();
}
