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
#include <algorithm>
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
  const QCommandLineOption size("size",
                                "with --screenshot the image's size (the view's, or with --window "
                                "the window's), else the window's: WIDTHxHEIGHT",
                                "WxH", "1280x800");
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

  // WIDTHxHEIGHT, both whole numbers in [64, 8192], nothing else.
  const QStringList edges = parser.value(size).split('x');
  bool widthOk = false, heightOk = false;
  const int width = edges.size() == 2 ? edges[0].toInt(&widthOk) : 0;
  const int height = edges.size() == 2 ? edges[1].toInt(&heightOk) : 0;
  if (!widthOk || !heightOk || std::min(width, height) < 64 || std::max(width, height) > 8192) {
    std::fprintf(stderr, "error: --size: '%s' is not WIDTHxHEIGHT with both in [64, 8192]\n",
                 parser.value(size).toStdString().c_str());
    return 1;
  }
  bool stepsOk = false;
  const int stepCount = parser.value(steps).toInt(&stepsOk);
  if (!stepsOk || stepCount < 0) {
    std::fprintf(stderr, "error: --steps: '%s' is not a whole number >= 0\n",
                 parser.value(steps).toStdString().c_str());
    return 1;
  }
  const bool oneShot = parser.isSet(screenshot);
  if (const QString problem =
          tetskin::gui::MainWindow::screenshotNameProblem(parser.value(screenshot));
      oneShot && !problem.isEmpty()) {
    std::fprintf(stderr, "error: %s: %s\n", parser.value(screenshot).toStdString().c_str(),
                 problem.toStdString().c_str());
    return 1;
  }
  tetskin::gui::MainWindow window(!oneShot);
  window.resize(width, height);
  window.show();
  QApplication::processEvents();
  if (oneShot && !parser.isSet(whole)) {
    // The image is the view's: --size is then its size, the window grown
    // by what the docks and bars take beside it.
    window.view()->setFixedSize(width, height);
    window.resize(window.minimumSizeHint());
    QApplication::processEvents();
  }
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
  // An unknown value is named with the option and the box's own entries
  // (the choices the dock offers), as the command line's errors are.
  const auto choose = [&window](const char* box, const char* option, const QString& value) {
    auto* combo = window.findChild<QComboBox*>(box);
    if (combo->findText(value) < 0) {
      QStringList choices;
      for (int i = 0; i < combo->count(); ++i) choices << combo->itemText(i);
      std::fprintf(stderr, "error: %s: '%s' is not one of %s\n", option,
                   value.toStdString().c_str(), choices.join(", ").toStdString().c_str());
      return false;
    }
    combo->setCurrentText(value);
    return true;
  };
  if (parser.isSet(camera) && !choose("camera", "--camera", parser.value(camera))) return 1;
  if (parser.isSet(control) && !choose("controlStyle", "--control", parser.value(control)))
    return 1;
  if (parser.isSet(colorBy) && !choose("colorBy", "--color-by", parser.value(colorBy))) return 1;
  if (parser.isSet(highlight)) window.findChild<QCheckBox*>("highlight")->setChecked(true);
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
