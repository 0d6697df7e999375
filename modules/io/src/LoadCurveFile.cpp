// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/LoadCurveFile.h"

#include <utility>
#include <vector>

#include "TextLines.h"
#include "tetskin/core/Error.h"

namespace tetskin {

LoadCurve readLoadCurve(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  std::vector<LoadCurve::Point> points;
  auto after = LoadCurve::After::Hold;
  while (lines.next()) {
    if (after == LoadCurve::After::Repeat)
      lines.fail("nothing may follow 'repeat' (it ends the curve)");
    if (lines.size() == 1 && lines[0] == "repeat") {
      if (points.size() < 2)
        lines.fail("'repeat' needs two points or more before it (their span is the period)");
      after = LoadCurve::After::Repeat;
      continue;
    }
    lines.expectTokens(2, 2, "load curve point (TIME FACTOR)");
    const LoadCurve::Point point{lines.toDouble(lines[0], "time"),
                                 lines.toDouble(lines[1], "factor")};
    if (auto problem = LoadCurve::pointProblem(points.empty() ? nullptr : &points.back(), point))
      lines.fail(*problem);
    points.push_back(point);
  }
  if (points.empty()) throw Error(path.string(), 0, "no points in the file (lines TIME FACTOR)");
  return LoadCurve(std::move(points), after);
}

}  // namespace tetskin
