// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/PointList.h"

#include "TextLines.h"
#include "tetskin/core/Error.h"

namespace tetskin {

PointList readPointList(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  detail::TextLines lines(content, path.string());
  std::vector<Eigen::Vector3d> points;
  PointList list;
  while (lines.next()) {
    lines.expectTokens(3, 3, "point (X Y Z)");
    Eigen::Vector3d p;
    for (std::size_t axis = 0; axis < 3; ++axis)
      p[static_cast<Index>(axis)] = lines.toDouble(lines[axis], "coordinate");
    points.push_back(p);
    list.lines.push_back(lines.lineNumber());
  }
  if (points.empty()) throw Error(path.string(), 0, "no points in the file (lines X Y Z)");
  list.points.resize(static_cast<Index>(points.size()), 3);
  for (std::size_t k = 0; k < points.size(); ++k)
    list.points.row(static_cast<Index>(k)) = points[k].transpose();
  return list;
}

}  // namespace tetskin
