// SPDX-License-Identifier: AGPL-3.0-or-later
#include "SeriesPlot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

namespace tetskin::gui {

SeriesPlot::SeriesPlot(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(90);
}

void SeriesPlot::setSeries(const std::vector<double>& times, const std::vector<double>& values,
                           const QString& title) {
  times_ = times;
  values_ = values;
  values_.resize(std::min(times_.size(), values_.size()));
  times_.resize(values_.size());
  title_ = title;
  update();
}

void SeriesPlot::setMarked(int sample) {
  marked_ = sample;
  update();
}

void SeriesPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  p.setPen(palette().text().color());
  p.drawText(4, 13, title_);
  if (values_.size() < 2) return;
  // From 0: an error is never negative, and its size beside 0 is the point.
  const double high = std::max(*std::max_element(values_.begin(), values_.end()), 1e-30);
  const double t0 = times_.front(), t1 = std::max(times_.back(), t0 + 1e-30);
  const QString top = QString::number(high, 'g', 3);
  const int left = 6 + p.fontMetrics().horizontalAdvance(top), right = width() - 4;
  const int upper = 18, lower = height() - 16;
  p.drawText(2, upper + 10, top);
  p.drawText(2, lower, "0");
  p.drawText(left, height() - 3, QString::number(t0, 'g', 3) + " s");
  const QString end = QString::number(t1, 'g', 3) + " s";
  p.drawText(right - p.fontMetrics().horizontalAdvance(end), height() - 3, end);
  const auto x = [&](double t) { return left + (t - t0) / (t1 - t0) * (right - left); };
  const auto y = [&](double v) { return lower - v / high * (lower - upper); };
  QPainterPath line;
  line.moveTo(x(times_[0]), y(values_[0]));
  for (std::size_t i = 1; i < values_.size(); ++i) line.lineTo(x(times_[i]), y(values_[i]));
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(QColor(200, 70, 50), 1.5));
  p.drawPath(line);
  if (marked_ >= 0 && marked_ < static_cast<int>(values_.size())) {
    const auto i = static_cast<std::size_t>(marked_);
    p.setPen(QPen(palette().text().color(), 1, Qt::DashLine));
    p.drawLine(QPointF(x(times_[i]), upper), QPointF(x(times_[i]), lower));
  }
}

}  // namespace tetskin::gui
