// SPDX-License-Identifier: AGPL-3.0-or-later
#include "CommandLine.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QPushButton>
#include <QSpinBox>
#include <cstdio>

#include "CompareDock.h"
#include "MainWindow.h"
#include "SimulationDock.h"
#include "ViewCapture.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/rendering/ImageSize.h"
#include "tetskin/session/RunSpecJson.h"

namespace tetskin::gui {
namespace {

bool usageError(const std::string& what) {
  std::fprintf(stderr, "error: %s\n", what.c_str());
  return false;
}

}  // namespace

GuiArguments::GuiArguments() {
  parser.setApplicationDescription(
      "TetSkin: inspect how a surface is bound to a simulated tetrahedral control mesh");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      "DATASET", "dataset (.json, a .node/.ele pair, a Gmsh .msh or a MEDIT .mesh)", "[DATASET]");
  parser.addPositionalArgument("SURFACE", "surface to bind (.obj .ply .stl .vtp)", "[SURFACE]");
  parser.addOptions({screenshot, whole, path, size, camera, control, colorBy, highlight, prescribed,
                     pick, scenario, steps, noOverlay, compare, printRun});
}

bool GuiArguments::read(const QStringList& arguments) {
  if (!parser.parse(arguments))
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
    return usageError(std::string(tetskin::recording_option::kSteps.flag) + ": '" +
                      parser.value(steps).toStdString() + "' is not a whole number >= 0");
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

std::optional<int> applyArguments(const GuiArguments& args, MainWindow& window) {
  const QCommandLineParser& parser = args.parser;
  const bool oneShot = parser.isSet(args.screenshot);
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
  if (parser.isSet(args.camera) &&
      !choose("camera", tetskin::kCameraOption.flag, parser.value(args.camera)))
    return 1;
  if (parser.isSet(args.control) &&
      !choose("controlStyle", tetskin::kControlMeshOption.flag, parser.value(args.control)))
    return 1;
  if (parser.isSet(args.colorBy) && !choose("colorBy", "--color-by", parser.value(args.colorBy)))
    return 1;
  if (parser.isSet(args.highlight)) window.findChild<QCheckBox*>("highlight")->setChecked(true);
  if (parser.isSet(args.prescribed))
    window.findChild<QCheckBox*>("showPrescribed")->setChecked(true);
  if (parser.isSet(args.noOverlay)) window.setOverlayVisible(false);
  if (parser.isSet(args.scenario)) {
    if (!choose("scenario", tetskin::kScenarioOption.flag, parser.value(args.scenario))) return 1;
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
    // As a user would: the Compare dock's levels and steps set, then its
    // Compare button, so that the dock shows what ran.
    if (!window.scene().hasDataset()) {
      std::fprintf(stderr, "error: --compare: open a dataset and a surface to compare levels\n");
      return 1;
    }
    int level = 0;
    try {
      level = tetskin::resolveLevel(window.scene().dataset().mesh, args.compareLevel);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: --compare: %s\n", e.what());
      return 1;
    }
    window.findChild<QSpinBox*>("compareReference")
        ->setValue(window.scene().dataset().mesh.finestLevel());
    window.findChild<QSpinBox*>("compareLevel")->setValue(level);
    if (parser.isSet(args.steps))
      window.findChild<QSpinBox*>("compareSteps")->setValue(args.stepCount);
    const QString errorBefore = window.lastError();
    window.findChild<QPushButton*>("compare")->click();
    if (window.lastError() != errorBefore && !window.lastError().isEmpty()) return fail();
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
  return std::nullopt;
}

}  // namespace tetskin::gui
