// SPDX-License-Identifier: AGPL-3.0-or-later
#include "CompareDock.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <utility>

#include "EnumBox.h"
#include "HistogramWidget.h"
#include "ScientificSpinBox.h"
#include "SeriesPlot.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/session/SimulationSession.h"

namespace tetskin::gui {
namespace {

const char* kDistance = "distance";
const char* kAngle = "normal angle";

QSpinBox* levelBox(const char* name) {
  auto* box = new QSpinBox;
  box->setObjectName(name);
  return box;
}

QString percentOf(double value, double diagonal) {
  return QString::number(100 * value / (diagonal > 0 ? diagonal : 1), 'g', 3) + "%";
}

}  // namespace

CompareDock::CompareDock(Scene& scene, QWidget* parent) : QWidget(parent), scene_(scene) {
  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  reference_ = levelBox("compareReference");
  reference_->setToolTip("the level the other is measured against (the finest, usually)");
  inspected_ = levelBox("compareLevel");
  inspected_->setToolTip("the level whose fidelity is shown");
  steps_ = levelBox("compareSteps");
  // (compare's own lower bound: 0 steps leave nothing to compare.)
  steps_->setRange(1, 100000);
  steps_->setValue(static_cast<int>(recording_option::kSteps.defaultValue));
  steps_->setToolTip("steps of the Simulation dock's scenario, run on both levels");
  form->addRow("Reference level", reference_);
  form->addRow("Inspected level", inspected_);
  form->addRow(labelOf(recording_option::kSteps), steps_);
  auto* run = new QPushButton("Compare");
  run->setObjectName("compare");
  run->setToolTip("run the Simulation dock's scenario, material and solver on both levels");
  form->addRow(run);
  connect(run, &QPushButton::clicked, this, [this] { Q_EMIT compareRequested(); });
  colouring_ = combo("compareColouring", {kDistance, kAngle});
  form->addRow("Colour by", colouring_);
  connect(colouring_, &QComboBox::currentTextChanged, this, [this] {
    showFrame();
    showVertex(vertex_);
  });
  layout->addLayout(form);
  summary_ = new QLabel("Compare two levels over the scenario.");
  summary_->setObjectName("compareSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(summary_);
  auto* frameRow = new QHBoxLayout;
  play_ = new QPushButton("Play");
  play_->setObjectName("comparePlay");
  play_->setCheckable(true);
  slider_ = new QSlider(Qt::Horizontal);
  slider_->setObjectName("compareFrame");
  frameRow->addWidget(play_);
  frameRow->addWidget(slider_);
  layout->addLayout(frameRow);
  frameText_ = new QLabel;
  frameText_->setObjectName("compareFrameText");
  layout->addWidget(frameText_);
  histogram_ = new HistogramWidget;
  histogram_->setObjectName("compareHistogram");
  layout->addWidget(histogram_);
  plot_ = new SeriesPlot;
  plot_->setObjectName("compareVertexPlot");
  layout->addWidget(plot_);
  close_ = new QPushButton("Close comparison");
  close_->setObjectName("compareClose");
  layout->addWidget(close_);
  layout->addStretch();
  timer_ = new QTimer(this);
  connect(slider_, &QSlider::valueChanged, this, [this] { showFrame(); });
  connect(play_, &QPushButton::toggled, this, [this](bool on) {
    play_->setText(on ? "Pause" : "Play");
    if (!on || !compared_) {
      timer_->stop();
      return;
    }
    if (slider_->value() == slider_->maximum()) slider_->setValue(0);
    // At the frames' own pace (a run of 1/60 s steps plays in real time).
    const double seconds = compared_->times.size() > 1
                               ? (compared_->times.back() - compared_->times.front()) /
                                     static_cast<double>(compared_->times.size() - 1)
                               : 0.1;
    timer_->start(std::max(1, static_cast<int>(1000 * seconds)));
  });
  connect(timer_, &QTimer::timeout, this, [this] {
    if (slider_->value() >= slider_->maximum()) {
      play_->setChecked(false);
      return;
    }
    slider_->setValue(slider_->value() + 1);
  });
  connect(close_, &QPushButton::clicked, this, [this] { close(); });
  close();
}

CompareDock::~CompareDock() = default;

void CompareDock::showDataset() {
  const int finest = scene_.dataset().mesh.finestLevel();
  reference_->setRange(0, finest);
  inspected_->setRange(0, finest);
  reference_->setValue(finest);
  inspected_->setValue(0);
}

int CompareDock::referenceLevel() const {
  return reference_->value();
}
int CompareDock::inspectedLevel() const {
  return inspected_->value();
}
int CompareDock::steps() const {
  return steps_->value();
}

void CompareDock::show(ComparedLevels compared) {
  auto deformer = std::make_unique<SurfaceDeformer>(compared.surface, compared.binding,
                                                    scene_.dataset().mesh.nodes);
  deformer_ = std::move(deformer);
  compared_ = std::move(compared);
  vertex_.reset();
  {
    const QSignalBlocker block(slider_);
    slider_->setRange(0, static_cast<int>(compared_->times.size()) - 1);
    slider_->setValue(0);
  }
  for (QWidget* w : std::initializer_list<QWidget*>{slider_, play_, close_, colouring_})
    w->setEnabled(true);
  showSummary();
  showFrame();
  showVertex(std::nullopt);
}

int CompareDock::frame() const {
  return compared_ ? slider_->value() : -1;
}

void CompareDock::setFrame(int frame) {
  slider_->setValue(frame);
}

void CompareDock::setColouring(const QString& name) {
  colouring_->setCurrentText(name);
}

bool CompareDock::byAngle() const {
  return colouring_->currentText() == kAngle;
}

void CompareDock::showSummary() {
  const ComparedLevels& c = *compared_;
  const ErrorSpread& e = c.overall;
  summary_->setText(
      QString("level %1 (%2 ms/step) against level %3 (%4 ms/step), over every vertex of %5 "
              "frames:\ndistance max %6, p99 %7, median %8 of the diagonal\nnormal angle max "
              "%9, p99 %10, median %11 degrees")
          .arg(c.inspected)
          .arg(1e3 * c.inspectedSecondsPerStep, 0, 'g', 3)
          .arg(c.reference)
          .arg(1e3 * c.referenceSecondsPerStep, 0, 'g', 3)
          .arg(c.times.size())
          .arg(percentOf(e.distance.max, c.diagonal), percentOf(e.distance.p99, c.diagonal),
               percentOf(e.distance.median, c.diagonal))
          .arg(e.angle.max, 0, 'g', 3)
          .arg(e.angle.p99, 0, 'g', 3)
          .arg(e.angle.median, 0, 'g', 3));
}

void CompareDock::showFrame() {
  if (!compared_) return;
  const ComparedLevels& c = *compared_;
  const auto f = static_cast<std::size_t>(slider_->value());
  SurfaceMesh deformed = c.surface;
  deformer_->deform(c.nodes[f], deformed.positions, deformed.normals);
  const std::vector<float>& values = byAngle() ? c.angle[f] : c.distance[f];
  const Eigen::VectorXd shown =
      Eigen::Map<const Eigen::VectorXf>(values.data(), static_cast<Index>(values.size()))
          .cast<double>();
  // One colour scale for the whole run: a frame's colours compare with another's.
  double largest = 0;
  for (const std::vector<float>& frame : byAngle() ? c.angle : c.distance)
    if (!frame.empty())
      largest = std::max(largest, double(*std::max_element(frame.begin(), frame.end())));
  const std::string title = byAngle() ? arrays::kNormalAngle : arrays::kSurfaceError;
  scene_.showComparison(deformed, shown, title, largest);
  histogram_->setValues(
      std::vector<double>(shown.data(), shown.data() + shown.size()),
      byAngle() ? "normal angle (degrees), this frame" : "distance from the reference, this frame");
  std::vector<double> sorted(shown.data(), shown.data() + shown.size());
  const Spread s = spreadOf(sorted);
  frameText_->setText(
      byAngle() ? QString("frame %1 of %2, %3 s: angle max %4, median %5 degrees")
                      .arg(f)
                      .arg(c.times.size() - 1)
                      .arg(c.times[f], 0, 'g', 4)
                      .arg(s.max, 0, 'g', 3)
                      .arg(s.median, 0, 'g', 3)
                : QString("frame %1 of %2, %3 s: distance max %4, median %5")
                      .arg(f)
                      .arg(c.times.size() - 1)
                      .arg(c.times[f], 0, 'g', 4)
                      .arg(percentOf(s.max, c.diagonal), percentOf(s.median, c.diagonal)));
  plot_->setMarked(static_cast<int>(f));
  Q_EMIT redraw();
}

void CompareDock::showVertex(std::optional<Index> vertex) {
  vertex_ = vertex;
  if (!compared_ || !vertex) {
    plot_->setSeries({}, {}, compared_ ? "click the surface: a vertex's error over time" : "");
    return;
  }
  std::vector<double> values;
  for (const std::vector<float>& frame : byAngle() ? compared_->angle : compared_->distance)
    values.push_back(frame[static_cast<std::size_t>(*vertex)]);
  plot_->setSeries(
      compared_->times, values,
      QString("vertex %1: %2").arg(*vertex).arg(byAngle() ? "normal angle (degrees)" : "distance"));
  plot_->setMarked(frame());
}

void CompareDock::close() {
  play_->setChecked(false);
  compared_.reset();
  deformer_.reset();
  vertex_.reset();
  scene_.hideComparison();
  for (QWidget* w : std::initializer_list<QWidget*>{slider_, play_, close_, colouring_})
    w->setEnabled(false);
  histogram_->setValues({}, "");
  plot_->setSeries({}, {}, "");
  frameText_->clear();
  Q_EMIT redraw();
}

}  // namespace tetskin::gui
