// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Polygons of the surface formats (OBJ, PLY) as triangles. Exporters write
// convex polygons mostly, but CAD and architectural models bring L-shaped
// and notched faces, and a fan from the first corner lays the triangles of
// such a face over each other, outside it: those are clipped ear by ear.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <vector>

namespace tetskin::detail {

// Appends polygon.size() - 2 triangles (none for fewer than 3 corners), each
// wound as the polygon. `positionOf(corner)` gives a corner's point (an
// Eigen::Vector3d). A strictly convex polygon is a fan from its first corner;
// any other is ear-clipped in the plane across its Newell normal, and what
// has no ear left (a polygon crossing itself) is fanned.
template <typename Corner, typename PositionOf>
void appendTriangles(const std::vector<Corner>& polygon, PositionOf positionOf,
                     std::vector<std::array<Corner, 3>>& triangles) {
  const std::size_t n = polygon.size();
  auto fan = [&](const std::vector<std::size_t>& order) {
    for (std::size_t k = 1; k + 1 < order.size(); ++k)
      triangles.push_back({polygon[order[0]], polygon[order[k]], polygon[order[k + 1]]});
  };
  std::vector<std::size_t> remaining(n);
  for (std::size_t k = 0; k < n; ++k) remaining[k] = k;
  if (n <= 3) return fan(remaining);

  std::vector<Eigen::Vector3d> points(n);
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // Newell's
  for (std::size_t k = 0; k < n; ++k) points[k] = positionOf(polygon[k]);
  for (std::size_t k = 0; k < n; ++k) normal += points[k].cross(points[(k + 1) % n]);
  int across = 0;
  normal.cwiseAbs().maxCoeff(&across);
  if (!(std::abs(normal[across]) > 0)) return fan(remaining);  // no area to clip in
  // The polygon in the coordinate plane it is most open to, turned so that
  // its corners run counter-clockwise.
  const int u = (across + 1) % 3, v = (across + 2) % 3;
  const double turn = normal[across] > 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> flat(n);
  for (std::size_t k = 0; k < n; ++k) flat[k] = {points[k][u], turn * points[k][v]};
  auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Eigen::Vector2d ab = flat[b] - flat[a], ac = flat[c] - flat[a];
    return ab.x() * ac.y() - ab.y() * ac.x();
  };

  bool convex = true;
  for (std::size_t k = 0; k < n && convex; ++k) convex = cross(k, (k + 1) % n, (k + 2) % n) > 0;
  if (convex) return fan(remaining);

  // An ear: a convex corner whose triangle holds no other corner (on its
  // edges included; corners at the same point as the ear's do not count).
  auto isEar = [&](std::size_t at) {
    const std::size_t m = remaining.size();
    const std::size_t a = remaining[(at + m - 1) % m], b = remaining[at],
                      c = remaining[(at + 1) % m];
    if (!(cross(a, b, c) > 0)) return false;
    for (std::size_t other : remaining) {
      if (other == a || other == b || other == c) continue;
      const Eigen::Vector2d& p = flat[other];
      if (p == flat[a] || p == flat[b] || p == flat[c]) continue;
      if (cross(a, b, other) >= 0 && cross(b, c, other) >= 0 && cross(c, a, other) >= 0)
        return false;
    }
    return true;
  };
  // (The search goes on from the last ear, as the next one is mostly
  // beside it: quadratic in the corners rather than cubic.)
  std::size_t at = 0;
  while (remaining.size() > 3) {
    std::size_t tried = 0;
    while (tried < remaining.size() && !isEar(at)) {
      at = (at + 1) % remaining.size();
      ++tried;
    }
    if (tried == remaining.size()) return fan(remaining);
    const std::size_t m = remaining.size();
    triangles.push_back({polygon[remaining[(at + m - 1) % m]], polygon[remaining[at]],
                         polygon[remaining[(at + 1) % m]]});
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(at));
    at = (at + m - 2) % (m - 1);  // the ear's previous corner
  }
  fan(remaining);
}

}  // namespace tetskin::detail
