// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A bar histogram of one binding quality array (MinBarycentric or Distance),
// with bins below zero drawn red: negative barycentric weights mean the vertex
// lies outside its control triangle.

#include <QWidget>
#include <vector>

namespace tetskin::gui {

class HistogramWidget : public QWidget {
  Q_OBJECT
 public:
  explicit HistogramWidget(QWidget* parent = nullptr);
  void setValues(const std::vector<double>& values, const QString& title, int bins = 40);
  const std::vector<int>& counts() const { return counts_; }
  double low() const { return low_; }
  double high() const { return high_; }
  QSize sizeHint() const override { return {260, 120}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::vector<int> counts_;
  double low_ = 0, high_ = 1;
  QString title_;
};

}  // namespace tetskin::gui
