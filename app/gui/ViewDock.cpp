// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ViewDock.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>
#include <algorithm>
#include <exception>

#include "EnumBox.h"
#include "ScientificSpinBox.h"

namespace tetskin::gui {

ViewDock::ViewDock(Scene& scene, QWidget* parent) : QWidget(parent), scene_(scene) {
  auto* form = new QFormLayout(this);
  renderPath_ = enumCombo("renderPath", kRenderPathOption, kDefaultRenderPath);
  form->addRow(labelOf(kRenderPathOption), renderPath_);
  connect(renderPath_, &QComboBox::currentTextChanged, this,
          [this](const QString& name) { Q_EMIT renderPathChosen(name); });
  auto toggle = [this, form](const char* name, const char* text, const char* label, auto set) {
    auto* box = new QCheckBox(text);
    box->setObjectName(name);
    form->addRow(label, box);
    connect(box, &QCheckBox::toggled, this, [this, set](bool on) {
      set(on);
      Q_EMIT redraw();
    });
    return box;
  };
  toggle("showSurface", "surface", "Show", [this](bool on) {
    scene_.setSurfaceVisible(on);
  })->setChecked(true);
  toggle("showFur", "fur (fur paths)", "", [this](bool on) {
    scene_.setFurVisible(on);
  })->setChecked(true);
  toggle("showPrescribed", "prescribed nodes (held or driven)", "",
         [this](bool on) { scene_.setPrescribedNodesShown(on); })
      ->setToolTip(
          "marks the simulated level's nodes that the scenario, the fixed nodes and the fixed "
          "box hold still or drive (a recorded run's while it is shown)");
  controlStyle_ = enumCombo("controlStyle", kControlMeshOption, ControlMeshStyle::Wireframe);
  form->addRow(labelOf(kControlMeshOption), controlStyle_);
  connect(controlStyle_, &QComboBox::currentTextChanged, this, [this] {
    scene_.setControlStyle(chosen<ControlMeshStyle>(controlStyle_));
    Q_EMIT redraw();
  });
  controlLevel_ = new QSpinBox;
  controlLevel_->setObjectName("controlLevel");
  form->addRow("Control level", controlLevel_);
  connect(controlLevel_, qOverload<int>(&QSpinBox::valueChanged), this, [this](int level) {
    scene_.setControlLevel(level);
    Q_EMIT redraw();
  });
  camera_ = enumCombo("camera", kCameraOption, kDefaultCamera);
  form->addRow(labelOf(kCameraOption), camera_);
  connect(camera_, &QComboBox::currentTextChanged, this, [this] {
    scene_.setCamera(chosen<CameraPreset>(camera_));
    Q_EMIT redraw();
  });
  // The dataset's up axis (its config's, or y): for a z-up model opened
  // as bare .node/.ele, or a config that does not say. The camera and the
  // next run follow it.
  upAxis_ = enumCombo("up", kUpOption, UpAxis::Y,
                      ": camera presets, scenarios, floor and gravity follow it");
  form->addRow(labelOf(kUpOption), upAxis_);
  connect(upAxis_, &QComboBox::currentTextChanged, this, [this] {
    if (!scene_.hasDataset()) return;
    scene_.setUpAxis(chosen<UpAxis>(upAxis_));
    Q_EMIT upAxisChanged();
  });
  const FurParameters fur;
  furShells_ = new QSpinBox;
  furShells_->setObjectName("furShells");
  furShells_->setRange(static_cast<int>(fur_option::kShells.range.min),
                       static_cast<int>(fur_option::kShells.range.max));
  furShells_->setValue(fur.shells);
  furShells_->setToolTip(fur_option::kShells.help);
  furLength_ = numberBox("furLength", fur_option::kLength);
  furLighting_ = enumCombo("furLighting", fur_option::kLighting, fur.lighting);
  furFins_ = new QCheckBox(fur_option::kFins.help);
  furFins_->setObjectName("furFins");
  furFins_->setChecked(fur_option::kFins.defaultValue);
  form->addRow(labelOf(fur_option::kShells), furShells_);
  form->addRow(labelOf(fur_option::kLength), furLength_);
  form->addRow(labelOf(fur_option::kLighting), furLighting_);
  form->addRow("", furFins_);
  auto furChanged = [this] {
    if (!scene_.hasDataset()) return;
    try {
      scene_.setFurParameters(furParameters());
    } catch (const std::exception& e) {
      Q_EMIT failed(e.what());
    }
    Q_EMIT redraw();
  };
  connect(furShells_, qOverload<int>(&QSpinBox::valueChanged), this, furChanged);
  connect(furLength_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, furChanged);
  connect(furLighting_, &QComboBox::currentTextChanged, this, furChanged);
  connect(furFins_, &QCheckBox::toggled, this, furChanged);
}

void ViewDock::showDataset() {
  const DatasetConfig& config = scene_.dataset().config;
  {
    const QSignalBlocker block(upAxis_);
    upAxis_->setCurrentText(toString(config.up));
  }
  {
    const QSignalBlocker block(controlLevel_);
    controlLevel_->setRange(0, static_cast<int>(scene_.dataset().mesh.levels.size()) - 1);
    controlLevel_->setValue(scene_.level());
  }
  const QSignalBlocker a(furShells_), b(furLength_), c(furLighting_), d(furFins_);
  furShells_->setValue(config.fur.shells);
  furLength_->setValue(config.fur.length);
  furLighting_->setCurrentText(toString(config.fur.lighting));
  furFins_->setChecked(config.fur.fins);
}

void ViewDock::setControlLevel(int level) {
  controlLevel_->setValue(level);
}

QString ViewDock::renderPath() const {
  return renderPath_->currentText();
}

void ViewDock::chooseRenderPath(const QString& name) {
  renderPath_->setCurrentText(name);
}

void ViewDock::showRenderPath(const QString& name) {
  const QSignalBlocker block(renderPath_);
  renderPath_->setCurrentText(name);
}

void ViewDock::chooseCamera(const QString& name) {
  camera_->setCurrentText(name);
}

FurParameters ViewDock::furParameters() const {
  FurParameters fur = scene_.hasDataset() ? scene_.dataset().config.fur : FurParameters{};
  fur.shells = furShells_->value();
  fur.minShells = std::min(fur.minShells, fur.shells);
  fur.length = furLength_->value();
  fur.lighting = chosen<FurLighting>(furLighting_);
  fur.fins = furFins_->isChecked();
  return fur;
}

}  // namespace tetskin::gui
