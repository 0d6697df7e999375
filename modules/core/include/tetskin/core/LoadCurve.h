// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A factor over time that scales loads, as the load curves of FE packages
// do: piecewise linear between points given in strictly increasing time,
// held at the first point's factor before it and at the last point's after
// it. The empty curve is 1 at all times (loads at their full value).

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

  LoadCurve() = default;
  // Throws Error naming the first bad point (from 1) and pointProblem()'s
  // words.
  explicit LoadCurve(std::vector<Point> points);

  // What is wrong with `point` following `previous` (none for the first):
  // a time or factor that is not finite, or a time not after the previous
  // one; nullopt when it may follow. The one check of a curve's points, for
  // the constructor and for readers that name a file's line.
  static std::optional<std::string> pointProblem(const Point* previous, const Point& point);

  double factorAt(double time) const;
  bool empty() const { return points_.empty(); }
  const std::vector<Point>& points() const { return points_; }

 private:
  std::vector<Point> points_;
};

// One line for people: "3 points from 0 to 2 s, factors 0 to 1" ("constant
// 1" for the empty curve).
std::string describe(const LoadCurve& curve);

}  // namespace tetskin
