// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The running simulation's energies over its last seconds of simulated
// time: kinetic, elastic, gravitational (from the rest shape, as
// Simulation measures it), the surface loads' potential where a run has
// surface loads, and their sum. A researcher sees a drop trade
// height for speed and the landing's losses, the body settle under
// damping, or a step size grow unstable, as it happens.

#include <QStringList>
#include <QWidget>
#include <deque>
#include <utility>

namespace tetskin::gui {

class EnergyPlot : public QWidget {
  Q_OBJECT
 public:
  struct Sample {
    double time = 0, kinetic = 0, elastic = 0, gravitational = 0, load = 0;
    double total() const { return kinetic + elastic + gravitational + load; }
  };
  explicit EnergyPlot(QWidget* parent = nullptr);
  // A sample at simulated `time`; one at an earlier time than the last
  // (a new run) starts the curves again. Samples older than `window`
  // seconds before the newest are dropped.
  void add(const Sample& sample);
  void clear();
  const std::deque<Sample>& samples() const { return samples_; }
  // Energies below `joules` are noise (round-off of a body at rest): the
  // legend reads them 0 and the curves are drawn on a scale of at least
  // this. The window sets it from the body (MainWindow::resetSimulation).
  void setNoiseFloor(double joules);
  // The legend as drawn: each curve's name and latest value, to the digits
  // that mean something beside the largest value shown ("elastic 0" at rest;
  // "load" only while a sample has a surface loads' potential).
  QStringList legend() const;
  double window() const { return window_; }
  QSize sizeHint() const override { return {260, 130}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  std::deque<Sample> samples_;
  double window_ = 10;  // seconds of simulated time shown
  double noiseFloor_ = 0;
  // The values' range over the window, with 0 in it.
  std::pair<double, double> range() const;
};

}  // namespace tetskin::gui
