// SPDX-License-Identifier: AGPL-3.0-or-later
#include "EnergyPlot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

namespace tetskin::gui {
namespace {

const QColor kKinetic(70, 130, 200);
const QColor kElastic(220, 130, 40);

}  // namespace

EnergyPlot::EnergyPlot(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(90);
  setToolTip("kinetic and elastic energy (J) over the last seconds of simulated time");
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

void EnergyPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  p.setRenderHint(QPainter::Antialiasing);
  const int top = 18, bottom = height() - 4, left = 4, right = width() - 4;
  p.setPen(palette().text().color());
  if (samples_.empty()) {
    p.drawText(left, 13, "energy: no simulation");
    return;
  }
  const Sample& last = samples_.back();
  // One scale for both curves, from 0: their sizes compare at a glance.
  double most = 0;
  for (const Sample& s : samples_) most = std::max({most, s.kinetic, s.elastic});
  if (!(most > 0)) most = 1;
  p.drawText(left, 13, QString("energy (J), max %1:").arg(most, 0, 'g', 3));
  const int legend = left + p.fontMetrics().horizontalAdvance(
                                QString("energy (J), max %1: ").arg(most, 0, 'g', 3));
  p.setPen(kKinetic);
  const QString kinetic = QString("kinetic %1").arg(last.kinetic, 0, 'g', 3);
  p.drawText(legend, 13, kinetic);
  p.setPen(kElastic);
  p.drawText(legend + p.fontMetrics().horizontalAdvance(kinetic + "  "), 13,
             QString("elastic %1").arg(last.elastic, 0, 'g', 3));
  const double start = std::max(samples_.front().time, last.time - window_);
  const double span = std::max(last.time - start, 1e-12);
  auto curve = [&](double Sample::*value, const QColor& color) {
    QPainterPath path;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      const QPointF point(left + (s.time - start) / span * (right - left),
                          bottom - s.*value / most * (bottom - top));
      if (i == 0)
        path.moveTo(point);
      else
        path.lineTo(point);
    }
    p.setPen(QPen(color, 1.5));
    p.drawPath(path);
  };
  curve(&Sample::kinetic, kKinetic);
  curve(&Sample::elastic, kElastic);
}

}  // namespace tetskin::gui
