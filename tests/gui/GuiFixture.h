// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The GUI tests' fixture: a non-interactive MainWindow shown at a fixed
// view size, as tetskin-gui opens it, with helpers that act as a user
// would (widgets found by object name, mouse events through Qt).
#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDropEvent>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QUrl>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

#include "BuildDialog.h"
#include "CompareDock.h"
#include "EnergyPlot.h"
#include "Frames.h"
#include "HistogramWidget.h"
#include "ImageCompare.h"
#include "MainWindow.h"
#include "MovieDecoding.h"
#include "SeriesPlot.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"
#include "vtkTetSkinBufferMapper.h"

namespace tetskin::gui {

inline const QString kData = QString(TETSKIN_SOURCE_DIR) + "/data/";

inline std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(TETSKIN_ACTUAL_DIR) / "scratch";
  std::filesystem::create_directories(dir);
  return dir / name;
}

class Gui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!QApplication::instance()) GTEST_SKIP() << "needs an X display (run under xvfb-run)";
    window_ = std::make_unique<MainWindow>(false);
    window_->setOverlayVisible(false);
    window_->view()->setFixedSize(400, 300);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override { window_.reset(); }

  void openSample() {
    ASSERT_TRUE(window_->openFiles({kData + "bunny.json", kData + "bunny.obj"}))
        << window_->lastError().toStdString();
  }
  template <class T>
  T* child(const char* name) {
    T* w = window_->findChild<T*>(name);
    EXPECT_NE(w, nullptr) << name;
    return w;
  }
  double changeFrom(vtkImageData* before) {
    return test::differingPixelShare(before, window_->grabImage());
  }
  // Mouse events as Qt delivers them to the view (QTest's own release does
  // not reach QVTKOpenGLNativeWidget's interactor).
  void mouse(QEvent::Type type, QPoint at, Qt::MouseButtons held,
             Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent event(type, at, window_->view()->mapToGlobal(at), button, held, modifiers);
    QApplication::sendEvent(window_->view(), &event);
  }
  // A click at VTK display coordinates (origin bottom left), through Qt.
  void click(int x, int y) {
    const QPoint at(x, window_->view()->height() - 1 - y);
    mouse(QEvent::MouseButtonPress, at, Qt::LeftButton);
    mouse(QEvent::MouseButtonRelease, at, Qt::NoButton);
  }
  // Display position of a world point.
  Eigen::Vector2d project(const Eigen::Vector3d& p) {
    vtkRenderer* r = window_->renderer();
    r->SetWorldPoint(p.x(), p.y(), p.z(), 1);
    r->WorldToDisplay();
    return {r->GetDisplayPoint()[0], r->GetDisplayPoint()[1]};
  }

  std::unique_ptr<MainWindow> window_;
};

}  // namespace tetskin::gui
