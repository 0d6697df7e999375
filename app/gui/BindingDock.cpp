// SPDX-License-Identifier: AGPL-3.0-or-later
#include "BindingDock.h"

#include <QCheckBox>
#include <QFont>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <vector>

#include "EnumBox.h"
#include "HistogramWidget.h"

namespace tetskin::gui {

namespace {
const char* kPickHint = "Click the surface to inspect a vertex; Shift+drag pulls the body.";
}

BindingDock::BindingDock(Scene& scene, QWidget* parent) : QWidget(parent), scene_(scene) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  colorBy_ = enumCombo("colorBy", ColorBy::Material);
  colorBy_->setToolTip("the surface's material, or an array of its binding");
  form->addRow("Colour by", colorBy_);
  connect(colorBy_, &QComboBox::currentTextChanged, this, [this] {
    scene_.setColorBy(chosen<ColorBy>(colorBy_));
    refresh();
    Q_EMIT redraw();
  });
  highlight_ = new QCheckBox("negative weights, far vertices");
  highlight_->setObjectName("highlight");
  form->addRow("Highlight", highlight_);
  connect(highlight_, &QCheckBox::toggled, this, [this](bool on) {
    scene_.setHighlightProblems(on);
    refresh();
    Q_EMIT redraw();
  });
  layout->addLayout(form);
  histogram_ = new HistogramWidget;
  histogram_->setObjectName("histogram");
  layout->addWidget(histogram_);
  vertexInfo_ = new QLabel(kPickHint);
  vertexInfo_->setObjectName("vertexInfo");
  vertexInfo_->setWordWrap(true);
  vertexInfo_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(vertexInfo_);
  auto* rebindRow = new QHBoxLayout;
  rebindMethod_ = enumCombo("rebindMethod", BindingMethod::Closest);
  rebindLevel_ = new QSpinBox;
  rebindLevel_->setObjectName("rebindLevel");
  auto* rebind = new QPushButton("Rebind");
  rebind->setObjectName("rebind");
  rebindRow->addWidget(rebindMethod_);
  rebindRow->addWidget(new QLabel("level"));
  rebindRow->addWidget(rebindLevel_);
  rebindRow->addWidget(rebind);
  layout->addLayout(rebindRow);
  connect(rebind, &QPushButton::clicked, this, [this] {
    Q_EMIT rebindRequested(chosen<BindingMethod>(rebindMethod_), rebindLevel_->value());
  });
  comparison_ = new QLabel;
  comparison_->setObjectName("comparison");
  comparison_->setWordWrap(true);
  comparison_->setFont(QFont("monospace", 8));
  layout->addWidget(comparison_);
  layout->addStretch();
}

void BindingDock::showDataset() {
  const QSignalBlocker block(rebindLevel_);
  rebindLevel_->setRange(0, static_cast<int>(scene_.dataset().mesh.levels.size()) - 1);
  rebindLevel_->setValue(scene_.level());
}

void BindingDock::refresh() {
  if (!scene_.hasSurface()) {
    histogram_->setValues({}, "no surface");
    comparison_->clear();
    return;
  }
  const SurfaceBinding& b = scene_.binding();
  const bool distance = scene_.colorBy() == ColorBy::Distance;
  const Eigen::VectorXd& values = distance ? b.distance : b.minBarycentric;
  histogram_->setValues(std::vector<double>(values.data(), values.data() + values.size()),
                        distance ? "Distance" : "MinBarycentric (red: outside)");
  QString comparison = QString::fromStdString(scene_.comparisonText());
  if (scene_.highlightedCount() > 0)
    comparison += QString("\nhighlighted: %1 vertices").arg(scene_.highlightedCount());
  // How far the bound level lies from the input it was built from (build).
  QString fidelity;
  const std::vector<LevelConfig>& levels = scene_.dataset().config.levels;
  if (scene_.level() >= 0 && static_cast<std::size_t>(scene_.level()) < levels.size())
    if (const auto& f = levels[static_cast<std::size_t>(scene_.level())].fidelity)
      fidelity = "level against its input: " + QString::fromStdString(describe(*f)) + "\n";
  comparison_->setText(QString("%1, level %2\n").arg(toString(b.method)).arg(scene_.level()) +
                       fidelity + comparison);
  showPickedVertex();
}

void BindingDock::showPickedVertex() {
  vertexInfo_->setText(pickedVertexText());
}

QString BindingDock::pickedVertexText() const {
  if (!scene_.pickedVertex()) return kPickHint;
  const VertexInfo i = scene_.vertexInfo(*scene_.pickedVertex());
  const int n = scene_.binding().controlsPerVertex();
  QString ids, weights;
  for (int k = 0; k < n; ++k) {
    ids += QString::number(i.controlIds[k]) + (k + 1 < n ? " " : "");
    weights += QString::number(i.weights[k], 'f', 4) + (k + 1 < n ? " " : "");
  }
  QString text =
      QString("vertex %1: element %2, control ids %3, weights %4, distance %5, min barycentric %6")
          .arg(i.vertex)
          .arg(i.face)
          .arg(ids, weights)
          .arg(i.distance, 0, 'g', 4)
          .arg(i.minBarycentric, 0, 'g', 4);
  // Its contact with the obstacles this frame (a run with obstacles).
  if (i.penetration)
    text += *i.penetration > 0 ? QString("; in contact: %1 inside, force %2 N")
                                     .arg(*i.penetration, 0, 'g', 3)
                                     .arg(i.contactForce.norm(), 0, 'g', 4)
                               : QString("; no contact");
  return text;
}

}  // namespace tetskin::gui
