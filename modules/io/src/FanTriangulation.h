// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Polygons of the surface formats (OBJ, PLY) as triangles: a fan from the
// first corner, exact for the convex polygons exporters write.

#include <array>
#include <vector>

namespace tetskin::detail {

// Appends polygon.size() - 2 triangles (none for fewer than 3 corners).
template <typename Corner>
void appendFan(const std::vector<Corner>& polygon, std::vector<std::array<Corner, 3>>& triangles) {
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
}

}  // namespace tetskin::detail
