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

struct CgalTriangleTree::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
};

CgalTriangleTree::CgalTriangleTree(const SurfaceMesh& surface) : impl_(std::make_unique<Impl>()) {
  impl_->triangles.reserve(static_cast<std::size_t>(surface.triangleCount()));
  for (Index f = 0; f < surface.triangleCount(); ++f) {
    const auto corner = [&](int k) {
      return point(surface.positions.row(surface.triangles(f, k)).transpose());
    };
    impl_->triangles.emplace_back(corner(0), corner(1), corner(2));
  }
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();  // (built here, before the threads query it)
}

CgalTriangleTree::~CgalTriangleTree() = default;

std::pair<Eigen::Vector3d, Index> CgalTriangleTree::closest(const Eigen::Vector3d& p) const {
  const auto nearest = impl_->tree.closest_point_and_primitive(point(p));
  return {Eigen::Vector3d(nearest.first.x(), nearest.first.y(), nearest.first.z()),
          nearest.second - impl_->triangles.cbegin()};
}

SurfaceBinding bindWithCgal(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level) {
  const LevelRange& r = mesh.levels[static_cast<std::size_t>(level)];
  SurfaceMesh boundary;
  boundary.triangles = boundaryFaces(extractLevel(mesh, level)).faces;
  boundary.positions = mesh.nodes.middleRows(r.firstNode, r.nodeCount);
  const CgalTriangleTree tree(boundary);
  const auto corner = [&](Index f, int k) -> Eigen::Vector3d {
    return boundary.positions.row(boundary.triangles(f, k)).transpose();
  };
  SurfaceBinding b;
  b.level = level;
  b.resize(surface.vertexCount());
  parallelFor<Index>(0, surface.vertexCount(), 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Vector3d p = surface.positions.row(v).transpose();
      const Index f = tree.closest(p).second;
      const Eigen::Vector3d w = planeBarycentric(p, corner(f, 0), corner(f, 1), corner(f, 2));
      for (int k = 0; k < 3; ++k) {
        b.controlIds(v, k) = boundary.triangles(f, k) + static_cast<int>(r.firstNode);
        b.weights(v, k) = w[k];
      }
      b.faceId[v] = static_cast<int>(f);
    }
  });
  return b;
}

}  // namespace tetskin::bench
