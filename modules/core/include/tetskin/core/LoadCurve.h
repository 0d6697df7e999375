// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A factor over time that scales loads, as the load curves of FE packages
// do: piecewise linear between points given in strictly increasing time,
// held at the first point's factor before it and, after the last, either
// held at the last point's factor or repeated (the span from the first
// point's time to the last's as its period: periodic forcing from one
// period's points). The empty curve is 1 at all times (loads at their full
// value).

#include <optional>
#include <string>
#include <vector>

namespace tetskin {

class LoadCurve {
 public:
  struct Point {
    double time;    // s
    double factor;  // times the loads
  };

  // What the curve does after its last point.
  enum class After { Hold, Repeat };

  LoadCurve() = default;
  // Throws Error naming the first bad point (from 1) and pointProblem()'s
  // words, and for a repeated curve of fewer than two points (no period).
  explicit LoadCurve(std::vector<Point> points, After after = After::Hold);

  // What is wrong with `point` following `previous` (none for the first):
  // a time or factor that is not finite, or a time not after the previous
  // one; nullopt when it may follow. The one check of a curve's points, for
  // the constructor and for readers that name a file's line.
  static std::optional<std::string> pointProblem(const Point* previous, const Point& point);

  double factorAt(double time) const;
  bool empty() const { return points_.empty(); }
  const std::vector<Point>& points() const { return points_; }
  After after() const { return after_; }

 private:
  std::vector<Point> points_;
  After after_ = After::Hold;
};

// One line for people: "3 points from 0 to 2 s, factors 0 to 1" (with ",
// repeated every 2 s" for a repeated curve; "constant 1" for the empty
// curve).
std::string describe(const LoadCurve& curve);

}  // namespace tetskin
