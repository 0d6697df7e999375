// SPDX-License-Identifier: AGPL-3.0-or-later
#include "EnergyPlot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "tetskin/core/NumberText.h"

namespace tetskin::gui {
namespace {

struct Curve {
  const char* name;
  double (*value)(const EnergyPlot::Sample&);
  QColor color;
  qreal width;
};

const std::array<Curve, 5> kCurves{{
    {"kinetic", [](const EnergyPlot::Sample& s) { return s.kinetic; }, QColor(70, 130, 200), 1.5},
    {"elastic", [](const EnergyPlot::Sample& s) { return s.elastic; }, QColor(220, 130, 40), 1.5},
    {"gravitational", [](const EnergyPlot::Sample& s) { return s.gravitational; },
     QColor(60, 160, 80), 1.5},
    {"load", [](const EnergyPlot::Sample& s) { return s.load; }, QColor(200, 90, 170), 1.5},
    {"total", [](const EnergyPlot::Sample& s) { return s.total(); }, QColor(90, 90, 90), 2.0},
}};

// The curves drawn: the load's only where a sample has one (a run with
// surface loads).
std::vector<const Curve*> shownCurves(const std::deque<EnergyPlot::Sample>& samples) {
  const bool loaded = std::any_of(samples.begin(), samples.end(),
                                  [](const EnergyPlot::Sample& s) { return s.load != 0; });
  std::vector<const Curve*> shown;
  for (const Curve& c : kCurves)
    if (loaded || std::string_view(c.name) != "load") shown.push_back(&c);
  return shown;
}

// Three digits of the plot's scale (its largest magnitude or the noise floor).
QString number(double value, double scale) {
  return QString::fromStdString(formatToScale(value, scale, 3));
}

}  // namespace

EnergyPlot::EnergyPlot(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(110);
  setToolTip(
      "kinetic, elastic and gravitational energy, the surface loads' potential (with surface "
      "loads) and their total (J) over the last seconds of simulated time; the potentials are "
      "measured from the rest shape");
}

void EnergyPlot::add(const Sample& sample) {
  if (!samples_.empty() && sample.time < samples_.back().time) samples_.clear();
  samples_.push_back(sample);
  while (samples_.front().time < sample.time - window_) samples_.pop_front();
  update();
}

void EnergyPlot::clear() {
  samples_.clear();
  update();
}

void EnergyPlot::setNoiseFloor(double joules) {
  noiseFloor_ = std::isfinite(joules) ? std::max(joules, 0.0) : 0.0;
  update();
}

std::pair<double, double> EnergyPlot::range() const {
  // One scale for all curves, with 0 in it: their sizes compare at a
  // glance, and the gravitational energy falls below 0 as a body sinks.
  double lowest = 0, highest = 0;
  const std::vector<const Curve*> curves = shownCurves(samples_);
  for (const Sample& s : samples_)
    for (const Curve* c : curves) {
      lowest = std::min(lowest, c->value(s));
      highest = std::max(highest, c->value(s));
    }
  // Noise is drawn flat, not magnified to the plot's height.
  if (!(highest - lowest > noiseFloor_)) highest = lowest + (noiseFloor_ > 0 ? noiseFloor_ : 1);
  return {lowest, highest};
}

QStringList EnergyPlot::legend() const {
  QStringList labels;
  if (samples_.empty()) return labels;
  const auto [lowest, highest] = range();
  const double scale = std::max({std::abs(lowest), std::abs(highest), noiseFloor_});
  for (const Curve* c : shownCurves(samples_))
    labels << QString("%1 %2").arg(c->name, number(c->value(samples_.back()), scale));
  return labels;
}

void EnergyPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  p.setRenderHint(QPainter::Antialiasing);
  const QFontMetrics metrics = p.fontMetrics();
  const int line = metrics.height();
  const int left = 4, right = width() - 4, bottom = height() - 4;
  p.setPen(palette().text().color());
  if (samples_.empty()) {
    p.drawText(left, line, "energy: no simulation");
    return;
  }
  const Sample& last = samples_.back();
  const auto [lowest, highest] = range();
  const double scale = std::max({std::abs(lowest), std::abs(highest), noiseFloor_});
  p.drawText(left, line,
             QString("energy (J), %1 to %2").arg(number(lowest, scale), number(highest, scale)));
  // The legend, with each curve's latest value, wrapped in a narrow dock.
  const QStringList labels = legend();
  const std::vector<const Curve*> curves = shownCurves(samples_);
  int x = left, baseline = 2 * line;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const Curve& c = *curves[i];
    const QString& label = labels[static_cast<int>(i)];
    const int advance = metrics.horizontalAdvance(label + "  ");
    if (x > left && x + metrics.horizontalAdvance(label) > right) {
      x = left;
      baseline += line;
    }
    p.setPen(c.color);
    p.drawText(x, baseline, label);
    x += advance;
  }
  const int top = baseline + 6;
  auto yOf = [&](double value) {
    return bottom - (value - lowest) / (highest - lowest) * (bottom - top);
  };
  if (lowest < 0) {  // the zero line
    p.setPen(QPen(palette().mid().color(), 1, Qt::DotLine));
    p.drawLine(QPointF(left, yOf(0)), QPointF(right, yOf(0)));
  }
  const double start = std::max(samples_.front().time, last.time - window_);
  const double span = std::max(last.time - start, 1e-12);
  for (const Curve* shown : curves) {
    const Curve& c = *shown;
    QPainterPath path;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      const QPointF point(left + (s.time - start) / span * (right - left), yOf(c.value(s)));
      if (i == 0)
        path.moveTo(point);
      else
        path.lineTo(point);
    }
    p.setPen(QPen(c.color, c.width));
    p.drawPath(path);
  }
}

}  // namespace tetskin::gui
