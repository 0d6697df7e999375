// SPDX-License-Identifier: AGPL-3.0-or-later
#include "CgalClosest.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <vector>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin::bench {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

SurfaceBinding bindWithCgal(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level) {
  const LevelRange& r = mesh.levels[static_cast<std::size_t>(level)];
  const Triangles faces = boundaryFaces(extractLevel(mesh, level)).faces;
  const auto corner = [&](Index f, int k) -> Eigen::Vector3d {
    return mesh.nodes.row(r.firstNode + faces(f, k)).transpose();
  };
  std::vector<Triangle> triangles;
  triangles.reserve(static_cast<std::size_t>(faces.rows()));
  for (Index f = 0; f < faces.rows(); ++f)
    triangles.emplace_back(point(corner(f, 0)), point(corner(f, 1)), point(corner(f, 2)));
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();  // (built here, before the threads query it)
  SurfaceBinding b;
  b.level = level;
  b.resize(surface.vertexCount());
  parallelFor<Index>(0, surface.vertexCount(), 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Vector3d p = surface.positions.row(v).transpose();
      const auto nearest = tree.closest_point_and_primitive(point(p));
      const Index f = nearest.second - triangles.cbegin();
      const Eigen::Vector3d w = planeBarycentric(p, corner(f, 0), corner(f, 1), corner(f, 2));
      for (int k = 0; k < 3; ++k) {
        b.controlIds(v, k) = faces(f, k) + static_cast<int>(r.firstNode);
        b.weights(v, k) = w[k];
      }
      b.faceId[v] = static_cast<int>(f);
    }
  });
  return b;
}

}  // namespace tetskin::bench
