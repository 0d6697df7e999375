// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui [DATASET.json] [SURFACE] [--screenshot FILE [--window]] [--path PATH]
//             [--size WxH] [--camera PRESET] [--control STYLE] [--color-by ARRAY]
//             [--highlight] [--prescribed] [--pick] [--scenario NAME] [--steps N]
//             [--no-overlay] [--compare LEVEL] [--print-run]
//             [--help] [--version]
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QPushButton>
#include <QSurfaceFormat>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "MainWindow.h"
#include "Scene.h"
#include "SimulationDock.h"
#include "ViewCapture.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/rendering/ControlMeshActor.h"
#include "tetskin/rendering/ImageSize.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/rendering/RenderPath.h"
#include "tetskin/rendering/XDisplay.h"
#include "tetskin/session/RunSpecJson.h"
#include "tetskin/simulation/Scenario.h"

namespace {

// "a, b or c": the names a choice offers (OptionSchema.h).
template <tetskin::SchemaEnum E>
QString choices() {
  return QString::fromStdString(tetskin::oneOf(tetskin::namesOf<E>()));
}

// The command line: declared once, read before a display is needed (help,
// version and usage errors work over ssh), and again once the QApplication
// has taken its own options (-platform, -style, ...) out.
struct GuiArguments {
  QCommandLineParser parser;
  QCommandLineOption screenshot{"screenshot", "render one frame to FILE (PNG) and exit", "FILE"};
  QCommandLineOption path{"path", choices<tetskin::RenderPath>(), "PATH", "cpu"};
  QCommandLineOption size{"size",
                          "with --screenshot the image's size (the view's, or with --window "
                          "the window's), else the window's: WIDTHxHEIGHT",
                          "WxH", "1280x800"};
  QCommandLineOption camera{"camera", choices<tetskin::CameraPreset>(), "PRESET", "iso"};
  QCommandLineOption whole{"window", "with --screenshot: the whole window, docks included"};
  QCommandLineOption control{"control", "control mesh: " + choices<tetskin::ControlMeshStyle>(),
                             "STYLE"};
  QCommandLineOption colorBy{"color-by", choices<tetskin::gui::ColorBy>(), "ARRAY"};
  QCommandLineOption highlight{"highlight", "mark vertices with negative weights or far"};
  QCommandLineOption prescribed{"prescribed",
                                "mark the nodes the simulation holds still or drives"};
  QCommandLineOption pick{"pick", "inspect the vertex at the centre of the view"};
  QCommandLineOption scenario{
      "scenario",
      QString::fromStdString(tetskin::oneOf(tetskin::scenarioNames())) + " (the Simulation dock's)",
      "NAME"};
  QCommandLineOption steps{"steps", "simulate N steps first (with --compare: compare over N)", "N",
                           "0"};
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

  GuiArguments() {
    parser.setApplicationDescription(
        "TetSkin: inspect how a surface is bound to a simulated tetrahedral control mesh");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        "DATASET", "dataset (.json, a .node/.ele pair, a Gmsh .msh or a MEDIT .mesh)", "[DATASET]");
    parser.addPositionalArgument("SURFACE", "surface to bind (.obj .ply .stl .vtp)", "[SURFACE]");
    parser.addOptions({screenshot, whole, path, size, camera, control, colorBy, highlight,
                       prescribed, pick, scenario, steps, noOverlay, compare, printRun});
  }

  // Parses the application's arguments; prints help or the version and
  // exits, or checks the values. false (after one line `error: ...`) on a
  // usage error.
  bool read(const QCoreApplication& app) {
    if (!parser.parse(app.arguments()))
      return usageError(parser.errorText().toStdString() + " (see tetskin-gui --help)");
    if (parser.isSet("help")) parser.showHelp(0);
    if (parser.isSet("version")) parser.showVersion();
    const std::string sizeText = parser.value(size).toStdString();
    const std::optional<tetskin::ImageSize> checkedSize = tetskin::parseImageSize(sizeText);
    if (!checkedSize) return usageError("--size: " + tetskin::imageSizeProblem(sizeText));
    width = checkedSize->width;
    height = checkedSize->height;
    bool stepsOk = false;
    stepCount = parser.value(steps).toInt(&stepsOk);
    if (!stepsOk || stepCount < 0)
      return usageError("--steps: '" + parser.value(steps).toStdString() +
                        "' is not a whole number >= 0");
    bool compareOk = true;
    if (parser.isSet(compare)) compareLevel = parser.value(compare).toInt(&compareOk);
    if (!compareOk)
      return usageError("--compare: '" + parser.value(compare).toStdString() +
                        "' is not a level (a whole number; negative from the finest)");
    if (const QString problem = tetskin::gui::screenshotNameProblem(parser.value(screenshot));
        parser.isSet(screenshot) && !problem.isEmpty())
      return usageError(parser.value(screenshot).toStdString() + ": " + problem.toStdString());
    return true;
  }

 private:
  static bool usageError(const std::string& what) {
    std::fprintf(stderr, "error: %s\n", what.c_str());
    return false;
  }
};

// Why Qt's default platform cannot open a window here, or empty. A platform
// chosen by QT_QPA_PLATFORM or -platform (e.g. offscreen) is Qt's to check;
// otherwise it is xcb, which aborts the process when it cannot connect.
std::string platformProblem(int argc, char** argv) {
  if (std::getenv("QT_QPA_PLATFORM")) return {};
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "-platform" || std::string_view(argv[i]) == "--platform")
      return {};
  return tetskin::xDisplayProblem();
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication::setOrganizationName("TetSkin");
  QCoreApplication::setApplicationName("tetskin-gui");
  QCoreApplication::setApplicationVersion(TETSKIN_VERSION);
  if (const std::string problem = platformProblem(argc, argv); !problem.empty()) {
    // Help, the version and usage errors need no window.
    const QCoreApplication plain(argc, argv);
    if (!GuiArguments().read(plain)) return 1;
    std::fprintf(stderr,
                 "error: tetskin-gui needs an X display (%s; for --screenshot run under "
                 "xvfb-run -a)\n",
                 problem.c_str());
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  GuiArguments args;
  if (!args.read(app)) return 1;
  const QCommandLineParser& parser = args.parser;
  const bool oneShot = parser.isSet(args.screenshot);
  tetskin::gui::MainWindow window(!oneShot);
  window.resize(args.width, args.height);
  window.show();
  QApplication::processEvents();
  if (!window.view()->isValid()) {
    // e.g. Qt's offscreen platform, or an X server without GLX: the view
    // would stay black and a screenshot empty.
    const char* message =
        "the view cannot create an OpenGL context on this display (for --screenshot without a "
        "display run under xvfb-run -a)";
    std::fprintf(stderr, "error: %s\n", message);
    if (!oneShot) QMessageBox::critical(&window, "TetSkin", message);
    return 1;
  }
  if (oneShot && !parser.isSet(args.whole)) {
    // The image is the view's: --size is then its size, the window grown
    // by what the docks and bars take beside it.
    window.view()->setFixedSize(args.width, args.height);
    window.resize(window.minimumSizeHint());
    QApplication::processEvents();
  }
  const auto fail = [&window] {
    std::fprintf(stderr, "error: %s\n", window.lastError().toStdString().c_str());
    return 1;
  };
  if (!window.openFiles(parser.positionalArguments()) && oneShot) return fail();
  if (parser.isSet(args.path)) {
    window.setRenderPath(parser.value(args.path));
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
  if (parser.isSet(args.camera) && !choose("camera", "--camera", parser.value(args.camera)))
    return 1;
  if (parser.isSet(args.control) &&
      !choose("controlStyle", "--control", parser.value(args.control)))
    return 1;
  if (parser.isSet(args.colorBy) && !choose("colorBy", "--color-by", parser.value(args.colorBy)))
    return 1;
  if (parser.isSet(args.highlight)) window.findChild<QCheckBox*>("highlight")->setChecked(true);
  if (parser.isSet(args.prescribed))
    window.findChild<QCheckBox*>("showPrescribed")->setChecked(true);
  if (parser.isSet(args.noOverlay)) window.setOverlayVisible(false);
  if (parser.isSet(args.scenario)) {
    if (!choose("scenario", "--scenario", parser.value(args.scenario))) return 1;
    window.findChild<QPushButton*>("reset")->click();  // as the dock applies it
    if (oneShot && !window.lastError().isEmpty()) return fail();
  }
  if (parser.isSet(args.printRun)) {
    if (!window.scene().hasDataset()) {
      std::fprintf(stderr, "error: --print-run: open a dataset\n");
      return 1;
    }
    try {
      std::printf("%s\n", tetskin::runSpecJson(window.simulationDock()->runSpec()).c_str());
      return 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --print-run: %s\n", e.what());
      return 1;
    }
  }
  if (parser.isSet(args.compare)) {
    if (!window.scene().hasDataset()) {
      std::fprintf(stderr, "error: --compare: open a dataset and a surface to compare levels\n");
      return 1;
    }
    try {
      const tetskin::MultiLevelTetMesh& mesh = window.scene().dataset().mesh;
      const int level = tetskin::resolveLevel(mesh, args.compareLevel);
      if (!window.compareLevels(mesh.finestLevel(), level, std::max(args.stepCount, 1)))
        return fail();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --compare: %s\n", e.what());
      return 1;
    }
    tetskin::gui::CompareDock& dock = *window.compareDock();
    dock.setFrame(static_cast<int>(dock.frameCount()) - 1);
  } else {
    for (int i = 0; i < args.stepCount; ++i) window.findChild<QPushButton*>("step")->click();
  }
  // Steps asked for but not taken (the simulation could not start: its
  // error is the window's last) must not pass for a simulated screenshot.
  if (oneShot && args.stepCount > 0 && !window.lastError().isEmpty()) return fail();
  if (parser.isSet(args.pick)) {
    window.renderNow();
    window.clickAt(window.view()->width() / 2, window.view()->height() / 2);
  }
  if (oneShot) {
    QApplication::processEvents();
    if (!window.saveScreenshot(parser.value(args.screenshot), parser.isSet(args.whole)))
      return fail();
    std::printf("wrote %s\n", parser.value(args.screenshot).toStdString().c_str());
    return 0;
  }
  return QApplication::exec();
}
