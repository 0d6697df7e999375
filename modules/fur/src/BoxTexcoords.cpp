// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/fur/BoxTexcoords.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

int dominantSide(const Eigen::Vector3d& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  return 2 * axis + (n[axis] < 0 ? 1 : 0);
}

BoxTexturedSurface boxTexcoords(const Points3& positions, const Triangles& triangles,
                                double tileSize) {
  if (!(tileSize > 0) || !std::isfinite(tileSize))
    throw Error("box texture coordinates: the tile size must be positive and finite");
  // Measured from the surface's lowest corner: the pattern belongs to the
  // shape wherever it is placed, and no coordinate is large (a model 1e6
  // away had texture coordinates of 1e8 tiles, beyond a float's 7 digits
  // on the GPU).
  const Eigen::RowVector3d corner = positions.rows() > 0
                                        ? Eigen::RowVector3d(positions.colwise().minCoeff())
                                        : Eigen::RowVector3d::Zero();
  auto at = [&](Index v) { return Eigen::Vector3d((positions.row(v) - corner).transpose()); };
  BoxTexturedSurface out;
  out.triangles.resize(triangles.rows(), 3);
  out.sides.resize(static_cast<std::size_t>(triangles.rows()));
  // copyOf[6 * v + side]: the split copy of vertex v for that side, or -1.
  std::vector<Index> copyOf(static_cast<std::size_t>(6 * positions.rows()), -1);
  for (Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d a = at(triangles(t, 0));
    const Eigen::Vector3d n = (at(triangles(t, 1)) - a).cross(at(triangles(t, 2)) - a);
    const int side = dominantSide(n);
    out.sides[static_cast<std::size_t>(t)] = side;
    for (int k = 0; k < 3; ++k) {
      const Index v = triangles(t, k);
      Index& copy = copyOf[static_cast<std::size_t>(6 * v + side)];
      if (copy < 0) {
        copy = static_cast<Index>(out.source.size());
        out.source.push_back(v);
      }
      out.triangles(t, k) = static_cast<int>(copy);
    }
  }
  // The side's two in-plane axes, ordered so the texture is not mirrored
  // when seen from outside (the tangent frame is right-handed with the normal).
  static constexpr std::array<std::array<int, 2>, 3> kPlane{{{1, 2}, {2, 0}, {0, 1}}};
  out.texcoords.resize(out.splitVertexCount(), 2);
  for (Index v = 0; v < positions.rows(); ++v)
    for (int side = 0; side < 6; ++side) {
      const Index copy = copyOf[static_cast<std::size_t>(6 * v + side)];
      if (copy < 0) continue;
      const auto& plane = kPlane[static_cast<std::size_t>(side / 2)];
      const double flip = (side % 2) ? -1.0 : 1.0;
      const Eigen::Vector3d p = at(v);
      out.texcoords(copy, 0) = flip * p[plane[0]] / tileSize;
      out.texcoords(copy, 1) = p[plane[1]] / tileSize;
    }
  return out;
}

void gatherSplit(const Points3& values, const std::vector<Index>& source, Points3& out) {
  out.resize(static_cast<Index>(source.size()), 3);
  for (std::size_t i = 0; i < source.size(); ++i)
    out.row(static_cast<Index>(i)) = values.row(source[i]);
}

}  // namespace tetskin
