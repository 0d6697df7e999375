// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One value over time as a line (the Compare dock's picked vertex: its
// distance from the reference over the run), with the range at the side
// and the frame shown marked.

#include <QString>
#include <QWidget>
#include <vector>

namespace tetskin::gui {

class SeriesPlot : public QWidget {
  Q_OBJECT
 public:
  explicit SeriesPlot(QWidget* parent = nullptr);
  // `values` at `times` (as many), under `title`; none: an empty plot
  // saying `title`.
  void setSeries(const std::vector<double>& times, const std::vector<double>& values,
                 const QString& title);
  // The sample marked (the frame shown); -1 for none.
  void setMarked(int sample);
  const std::vector<double>& values() const { return values_; }
  QSize sizeHint() const override { return {260, 110}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::vector<double> times_, values_;
  QString title_;
  int marked_ = -1;
};

}  // namespace tetskin::gui
