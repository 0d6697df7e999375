// SPDX-License-Identifier: AGPL-3.0-or-later
// GoogleTest main with a QApplication; listing the tests needs no display.
#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QSettings>
#include <QSurfaceFormat>

#include "tetskin/rendering/XDisplay.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests) || !tetskin::xDisplayProblem().empty())
    return RUN_ALL_TESTS();  // tests skip
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TetSkin");
  QApplication::setApplicationName("tetskin-gui-tests");
  // Recent files and other settings go to the build tree, not the user's home;
  // one folder per process (CTest runs each test in its own), since QSettings
  // notices another process's writes to a shared file only by its timestamp.
  QSettings::setPath(
      QSettings::NativeFormat, QSettings::UserScope,
      QDir::currentPath() + "/gui_settings/" + QString::number(QCoreApplication::applicationPid()));
  QSettings().clear();
  return RUN_ALL_TESTS();
}
