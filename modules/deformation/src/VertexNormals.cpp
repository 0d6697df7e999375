// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/deformation/VertexNormals.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "tetskin/core/Parallel.h"

namespace tetskin {

VertexTriangleAdjacency vertexTriangleAdjacency(const Triangles& triangles, Index vertexCount) {
  VertexTriangleAdjacency a;
  a.offsets.assign(static_cast<std::size_t>(vertexCount) + 1, 0);
  for (Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) ++a.offsets[static_cast<std::size_t>(triangles(t, k)) + 1];
  for (std::size_t v = 1; v < a.offsets.size(); ++v) a.offsets[v] += a.offsets[v - 1];
  a.triangles.resize(static_cast<std::size_t>(a.offsets.back()));
  std::vector<int> fill(a.offsets.begin(), a.offsets.end() - 1);
  for (Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      a.triangles[static_cast<std::size_t>(fill[static_cast<std::size_t>(triangles(t, k))]++)] =
          static_cast<int>(t);
  return a;
}

namespace {

// Twice the area times the unit normal: area weighting for free.
Eigen::Vector3d faceNormal(const ConstPoints3Ref& positions, const Triangles& triangles, Index t) {
  const Eigen::Vector3d a = positions.row(triangles(t, 0));
  const Eigen::Vector3d b = positions.row(triangles(t, 1));
  const Eigen::Vector3d c = positions.row(triangles(t, 2));
  return (b - a).cross(c - a);
}

// A summed normal made unit, or the zero vector where there is no area.
Eigen::Vector3d unit(Eigen::Vector3d n) {
  const double length = n.norm();
  if (length > 0) n /= length;
  return n;
}

}  // namespace

void computeVertexNormals(const ConstPoints3Ref& positions, const Triangles& triangles,
                          const VertexTriangleAdjacency& adjacency, Points3& faceScratch,
                          Points3Ref normals) {
  constexpr Index kGrain = 4096;
  parallelFor<Index>(0, triangles.rows(), kGrain, [&](const auto& r) {
    for (Index t = r.begin(); t != r.end(); ++t)
      faceScratch.row(t) = faceNormal(positions, triangles, t).transpose();
  });
  parallelFor<Index>(0, positions.rows(), kGrain, [&](const auto& r) {
    for (Index v = r.begin(); v != r.end(); ++v) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (int i = adjacency.offsets[static_cast<std::size_t>(v)];
           i < adjacency.offsets[static_cast<std::size_t>(v) + 1]; ++i)
        n += faceScratch.row(adjacency.triangles[static_cast<std::size_t>(i)]).transpose();
      normals.row(v) = unit(n).transpose();
    }
  });
}

Points3 vertexNormals(const Points3& positions, const Triangles& triangles) {
  const VertexTriangleAdjacency adjacency = vertexTriangleAdjacency(triangles, positions.rows());
  Points3 faces(triangles.rows(), 3), normals(positions.rows(), 3);
  computeVertexNormals(positions, triangles, adjacency, faces, normals);
  return normals;
}

Points3 vertexNormalsOf(const ConstPoints3Ref& positions, const Triangles& triangles,
                        const std::vector<Index>& vertices) {
  Points3 sums = Points3::Zero(static_cast<Index>(vertices.size()), 3);
  if (vertices.empty()) return sums;
  // (A bit a vertex screens the corners; the sum's order is the triangles',
  // as in the adjacency computeVertexNormals gathers over.)
  std::vector<bool> wanted(static_cast<std::size_t>(positions.rows()), false);
  for (Index v : vertices) wanted[static_cast<std::size_t>(v)] = true;
  for (Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index v = triangles(t, k);
      if (!wanted[static_cast<std::size_t>(v)]) continue;
      const auto slot = std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin();
      sums.row(slot) += faceNormal(positions, triangles, t).transpose();
    }
  for (Index i = 0; i < sums.rows(); ++i) sums.row(i) = unit(sums.row(i).transpose()).transpose();
  return sums;
}

}  // namespace tetskin
