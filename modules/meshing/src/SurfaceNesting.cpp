// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/SurfaceNesting.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include "SurfaceEdges.h"
#include "tetskin/spatial/Aabb.h"

namespace tetskin {
namespace {

Eigen::Vector3d corner(const SurfaceMesh& mesh, int t, int k) {
  return mesh.positions.row(mesh.triangles(t, k)).transpose();
}

// The triangle of `part` of largest area: its centroid lies on the part and
// away from the others (parts meet at most at vertices and edges), and its
// normal is well defined.
int largestTriangle(const SurfaceMesh& mesh, const std::vector<int>& part) {
  int best = part.front();
  double bestArea = -1;
  for (int t : part) {
    const double area = triangleArea(corner(mesh, t, 0), corner(mesh, t, 1), corner(mesh, t, 2));
    if (area > bestArea) best = t, bestArea = area;
  }
  return best;
}

Eigen::Vector3d centroid(const SurfaceMesh& mesh, int t) {
  return (corner(mesh, t, 0) + corner(mesh, t, 1) + corner(mesh, t, 2)) / 3;
}

Aabb partBox(const SurfaceMesh& mesh, const std::vector<int>& part) {
  Aabb box;
  for (int t : part)
    for (int k = 0; k < 3; ++k) box.extend(corner(mesh, t, k));
  return box;
}

// Distance along the ray origin + s direction (s > minimum) to the nearest
// triangle of the mesh other than `skip` (Moeller-Trumbore); infinity when
// it hits none.
double rayHit(const SurfaceMesh& mesh, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& direction, int skip, double minimum) {
  double nearest = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    if (t == skip) continue;
    const Eigen::Vector3d a = corner(mesh, static_cast<int>(t), 0);
    const Eigen::Vector3d e1 = corner(mesh, static_cast<int>(t), 1) - a;
    const Eigen::Vector3d e2 = corner(mesh, static_cast<int>(t), 2) - a;
    const Eigen::Vector3d p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;  // parallel
    const Eigen::Vector3d s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double distance = e2.dot(q) / det;
    if (distance > minimum) nearest = std::min(nearest, distance);
  }
  return nearest;
}

// A point just inside the region `part` encloses, off every triangle: from
// the middle of the part's largest triangle into that region, halfway to
// the next surface, however the region is shaped. (A point on the part
// would do for a winding number but for a part touching it face to face,
// where the formula jumps.) `diagonal` scales the smallest distance taken
// as a hit.
Eigen::Vector3d interiorPoint(const SurfaceMesh& mesh, const std::vector<int>& part,
                              double diagonal) {
  const int t = largestTriangle(mesh, part);
  const Eigen::Vector3d start = centroid(mesh, t);
  const Eigen::Vector3d normal =
      triangleNormal(corner(mesh, t, 0), corner(mesh, t, 1), corner(mesh, t, 2));
  // The normal points into the region where the part is wound inward.
  const Eigen::Vector3d inward = partVolume(mesh, part) < 0 ? normal : Eigen::Vector3d(-normal);
  const double hit = rayHit(mesh, start, inward, t, 1e-12 * diagonal);
  // (A closed part is always hit; a flat one, of no volume, may not be.)
  return start + (std::isfinite(hit) ? 0.5 * hit : 1e-9 * diagonal) * inward;
}

}  // namespace

double partVolume(const SurfaceMesh& mesh, const std::vector<int>& part) {
  if (part.empty()) return 0;
  // (Measured from a corner of the part: accurate far from the origin.)
  const Eigen::Vector3d origin = corner(mesh, part.front(), 0);
  double volume = 0;
  for (int t : part)
    volume += signedTetVolume(origin, corner(mesh, t, 0), corner(mesh, t, 1), corner(mesh, t, 2));
  return volume;
}

SurfaceParts surfaceParts(const SurfaceMesh& mesh) {
  const auto edges = edgeTriangles(mesh);
  const auto n = static_cast<std::size_t>(mesh.triangleCount());
  SurfaceParts parts;
  parts.reachedFrom.assign(n, -1);
  std::vector<char> seen(n, 0);
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (seen[seed]) continue;
    std::vector<int>& part = parts.triangles.emplace_back();
    std::queue<int> queue;
    queue.push(static_cast<int>(seed));
    seen[seed] = 1;
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop();
      part.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const auto& users = edges.at(edgeKey(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3)));
        if (users.size() != 2) continue;  // open or non-manifold: joins nothing
        const int u = users[0] == t ? users[1] : users[0];
        if (seen[static_cast<std::size_t>(u)]) continue;
        seen[static_cast<std::size_t>(u)] = 1;
        parts.reachedFrom[static_cast<std::size_t>(u)] = t;
        queue.push(u);
      }
    }
  }
  return parts;
}

double windingNumber(const SurfaceMesh& mesh, const std::vector<int>& part,
                     const Eigen::Vector3d& point) {
  double solidAngle = 0;
  for (int t : part) {
    const Eigen::Vector3d a = corner(mesh, t, 0) - point, b = corner(mesh, t, 1) - point,
                          c = corner(mesh, t, 2) - point;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    // Van Oosterom and Strackee's formula for the solid angle of a triangle.
    solidAngle += 2 * std::atan2(a.dot(b.cross(c)),
                                 la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return solidAngle / (4 * std::numbers::pi);
}

std::vector<std::vector<int>> enclosingParts(const SurfaceMesh& mesh,
                                             const std::vector<std::vector<int>>& parts) {
  std::vector<Aabb> boxes;
  std::vector<Eigen::Vector3d> probes;
  const double diagonal = boundingBox(mesh).diagonal();
  for (const auto& part : parts) {
    boxes.push_back(partBox(mesh, part));
    probes.push_back(interiorPoint(mesh, part, diagonal));
  }
  std::vector<std::vector<int>> enclosing(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = 0; j < parts.size(); ++j) {
      // (The box test spares the winding number for all but a few pairs.)
      if (i == j || !boxes[j].contains(probes[i])) continue;
      if (std::abs(windingNumber(mesh, parts[j], probes[i])) > 0.5)
        enclosing[i].push_back(static_cast<int>(j));
    }
  return enclosing;
}

std::vector<char> cavityParts(const SurfaceMesh& mesh, const std::vector<std::vector<int>>& parts,
                              const std::vector<std::vector<int>>& enclosing) {
  std::vector<int> sign;
  for (const auto& part : parts) sign.push_back(partVolume(mesh, part) < 0 ? -1 : 1);
  std::vector<char> cavity(parts.size(), 0);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    // Just inside part i lie only it and the parts that enclose it (parts
    // do not cross one another).
    int winding = sign[i];
    for (int j : enclosing[i]) winding += sign[static_cast<std::size_t>(j)];
    cavity[i] = winding == 0;
  }
  return cavity;
}

std::vector<Eigen::Vector3d> cavityPoints(const SurfaceMesh& mesh) {
  const std::vector<std::vector<int>> parts = surfaceParts(mesh).triangles;
  const std::vector<char> cavity = cavityParts(mesh, parts, enclosingParts(mesh, parts));
  std::vector<Eigen::Vector3d> points;
  const double diagonal = boundingBox(mesh).diagonal();
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (cavity[i]) points.push_back(interiorPoint(mesh, parts[i], diagonal));
  return points;
}

}  // namespace tetskin
