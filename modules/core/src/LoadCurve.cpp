// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/LoadCurve.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tetskin/core/Error.h"

namespace tetskin {

LoadCurve::LoadCurve(std::vector<Point> points, After after)
    : points_(std::move(points)), after_(after) {
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (auto problem = pointProblem(i > 0 ? &points_[i - 1] : nullptr, points_[i]))
      throw Error("load curve point " + std::to_string(i + 1) + ": " + *problem);
  if (after_ == After::Repeat && points_.size() < 2)
    throw Error("a repeated load curve needs two points or more (its period is their span)");
}

std::optional<std::string> LoadCurve::pointProblem(const Point* previous, const Point& point) {
  if (!std::isfinite(point.time)) return "the time must be finite, got " + formatNumber(point.time);
  if (!std::isfinite(point.factor))
    return "the factor must be finite, got " + formatNumber(point.factor);
  if (previous && !(point.time > previous->time))
    return "the times must increase, but " + formatNumber(point.time) + " s follows " +
           formatNumber(previous->time) + " s";
  return std::nullopt;
}

double LoadCurve::factorAt(double time) const {
  if (points_.empty()) return 1;
  if (!(time > points_.front().time)) return points_.front().factor;  // (NaN: the first)
  if (time >= points_.back().time) {
    if (after_ == After::Hold) return points_.back().factor;
    const double period = points_.back().time - points_.front().time;
    time = points_.front().time + std::fmod(time - points_.front().time, period);
  }
  // The first point after `time`; the one before it is at or before `time`.
  const auto after = std::upper_bound(points_.begin(), points_.end(), time,
                                      [](double t, const Point& p) { return t < p.time; });
  if (after == points_.end()) return points_.back().factor;  // (a repeat rounded up to the end)
  const Point& a = *(after - 1);
  const Point& b = *after;
  const double s = (time - a.time) / (b.time - a.time);
  return a.factor + s * (b.factor - a.factor);
}

std::string describe(const LoadCurve& curve) {
  if (curve.empty()) return "constant 1";
  const auto& points = curve.points();
  if (points.size() == 1) return "constant " + formatNumber(points.front().factor);
  const auto [low, high] = std::minmax_element(
      points.begin(), points.end(),
      [](const LoadCurve::Point& a, const LoadCurve::Point& b) { return a.factor < b.factor; });
  const double span = points.back().time - points.front().time;
  return std::to_string(points.size()) + " points from " + formatNumber(points.front().time) +
         " to " + formatNumber(points.back().time) + " s, factors " + formatNumber(low->factor) +
         " to " + formatNumber(high->factor) +
         (curve.after() == LoadCurve::After::Repeat
              ? ", repeated every " + formatNumber(span) + " s"
              : "");
}

}  // namespace tetskin
