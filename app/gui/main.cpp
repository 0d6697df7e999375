// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin-gui: the window, with the command line CommandLine.h declares.
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "CommandLine.h"
#include "MainWindow.h"
#include "tetskin/rendering/XDisplay.h"

namespace {

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
    if (!tetskin::gui::GuiArguments().read(plain)) return 1;
    std::fprintf(stderr,
                 "error: tetskin-gui needs an X display (%s; for --screenshot run under "
                 "xvfb-run -a)\n",
                 problem.c_str());
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  tetskin::gui::GuiArguments args;
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
  if (const std::optional<int> status = tetskin::gui::applyArguments(args, window)) return *status;
  return QApplication::exec();
}
