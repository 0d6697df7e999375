// SPDX-License-Identifier: AGPL-3.0-or-later
#include "HistogramWidget.h"

#include <QPainter>
#include <algorithm>
#include <cmath>

namespace tetskin::gui {

HistogramWidget::HistogramWidget(QWidget* parent) : QWidget(parent) {
  setMinimumHeight(100);
}

void HistogramWidget::setValues(const std::vector<double>& values, const QString& title, int bins) {
  title_ = title;
  counts_.assign(static_cast<std::size_t>(std::max(bins, 1)), 0);
  if (values.empty()) {
    update();
    return;
  }
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  low_ = *lo;
  high_ = *hi > *lo ? *hi : *lo + 1;
  const double width = (high_ - low_) / static_cast<double>(counts_.size());
  for (double v : values) {
    auto bin = static_cast<std::size_t>(std::floor((v - low_) / width));
    ++counts_[std::min(bin, counts_.size() - 1)];
  }
  update();
}

void HistogramWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  const int top = 18, bottom = height() - 16;
  p.setPen(palette().text().color());
  p.drawText(4, 13, title_);
  p.drawText(4, height() - 3, QString::number(low_, 'g', 3));
  const QString hi = QString::number(high_, 'g', 3);
  p.drawText(width() - 4 - p.fontMetrics().horizontalAdvance(hi), height() - 3, hi);
  if (counts_.empty()) return;
  const int most = std::max(1, *std::max_element(counts_.begin(), counts_.end()));
  const double barWidth = static_cast<double>(width() - 8) / static_cast<double>(counts_.size());
  const double binWidth = (high_ - low_) / static_cast<double>(counts_.size());
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    // Log scale: the few bad vertices stay visible beside the many good ones.
    const double share = std::log1p(counts_[i]) / std::log1p(most);
    const int h = static_cast<int>(share * (bottom - top));
    const bool negative = low_ + (static_cast<double>(i) + 1) * binWidth <= 0;
    p.fillRect(
        QRectF(4 + static_cast<double>(i) * barWidth, bottom - h, std::max(1.0, barWidth - 1), h),
        negative ? QColor(220, 60, 50) : QColor(70, 130, 200));
  }
}

}  // namespace tetskin::gui
