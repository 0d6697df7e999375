// SPDX-License-Identifier: AGPL-3.0-or-later
// The one place TetSkin includes CGAL: its headers are heavy to compile.
#include "tetskin/meshing/AlphaWrap.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

namespace tetskin {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// A hole whose patch would cover at most this share of the surface's area
// is closed before the wrap: a scan's missing base or an occlusion. A wider
// one is the rim of an open sheet (a face, a mask: its patch would be about
// as large as the sheet), which the wrap turns into a shell instead.
constexpr double kFilledHoleArea = 0.25;

}  // namespace

SurfaceMesh wrapReady(const SurfaceMesh& input, const RepairOptions& repair, Index* holesClosed) {
  SurfaceMesh mesh = input;
  const double diagonal = boundingBox(mesh).diagonal();
  const RepairTolerances tolerance = repairTolerances(repair, diagonal);
  weldVertices(mesh, tolerance.weld);
  splitTJunctions(mesh, tolerance.tJunction);
  SurfaceMesh withoutFlaps = mesh;
  removeFlaps(withoutFlaps);
  if (hasArea(withoutFlaps)) mesh = std::move(withoutFlaps);
  const Index closed = fillHoles(mesh, kFilledHoleArea * surfaceArea(mesh));
  if (holesClosed) *holesClosed = closed;
  return mesh;
}

bool hasArea(const SurfaceMesh& mesh) {
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    if (triangleArea(mesh.positions.row(mesh.triangles(t, 0)).transpose(),
                     mesh.positions.row(mesh.triangles(t, 1)).transpose(),
                     mesh.positions.row(mesh.triangles(t, 2)).transpose()) > 0)
      return true;
  return false;
}

SurfaceMesh alphaWrap(const SurfaceMesh& input, double alpha, double offset,
                      const std::string& name) {
  validateSurface(input, name);
  if (!(alpha > 0) || !std::isfinite(alpha))
    throw Error(name, 0, "the wrap's alpha must be a positive number");
  if (!(offset > 0) || !std::isfinite(offset))
    throw Error(name, 0, "the wrap's offset must be a positive number");
  if (!hasArea(input))
    throw Error(name, 0,
                input.triangleCount() == 0
                    ? "the surface has no triangles: there is nothing to wrap"
                    : "every triangle of the surface has zero area: there is nothing to wrap");
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(input.vertexCount()));
  for (Index v = 0; v < input.vertexCount(); ++v)
    points.emplace_back(input.positions(v, 0), input.positions(v, 1), input.positions(v, 2));
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(static_cast<std::size_t>(input.triangleCount()));
  for (Index t = 0; t < input.triangleCount(); ++t)
    faces.push_back({static_cast<std::size_t>(input.triangles(t, 0)),
                     static_cast<std::size_t>(input.triangles(t, 1)),
                     static_cast<std::size_t>(input.triangles(t, 2))});
  Mesh wrap;
  CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
  if (wrap.number_of_faces() == 0) throw Error(name, 0, "the alpha wrap came out empty");

  SurfaceMesh out;
  out.positions.resize(static_cast<Index>(wrap.number_of_vertices()), 3);
  std::vector<int> index(wrap.num_vertices(), -1);  // (no removed vertices in a fresh mesh)
  int next = 0;
  for (const Mesh::Vertex_index v : wrap.vertices()) {
    const Point& p = wrap.point(v);
    out.positions.row(next) << p.x(), p.y(), p.z();
    index[static_cast<std::size_t>(v)] = next++;
  }
  out.triangles.resize(static_cast<Index>(wrap.number_of_faces()), 3);
  Index row = 0;
  for (const Mesh::Face_index f : wrap.faces()) {
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(wrap.halfedge(f), wrap)) {
      if (k == 3) throw Error(name, 0, "the alpha wrap has a face that is not a triangle");
      out.triangles(row, k++) = index[static_cast<std::size_t>(v)];
    }
    ++row;
  }
  // CGAL winds the wrap outward; a wrap wound inward would mesh as a cavity.
  if (enclosedVolume(out) < 0) out.triangles.col(1).swap(out.triangles.col(2));
  return out;
}

WrapFidelity wrapFidelity(const SurfaceMesh& input, const SurfaceMesh& wrap) {
  WrapFidelity f;
  f.inputToWrap = oneSidedDistance(input, wrap);
  f.wrapToInput = oneSidedDistance(wrap, input);
  f.diagonal = boundingBox(input).diagonal();
  return f;
}

double meanThickness(const SurfaceMesh& closed) {
  const double area = surfaceArea(closed);
  return area > 0 ? 2.0 * std::abs(enclosedVolume(closed)) / area : 0.0;
}

}  // namespace tetskin
