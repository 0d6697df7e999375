// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/SurfaceRepair.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "SurfaceEdges.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/meshing/SurfaceNesting.h"
#include "tetskin/spatial/AabbTree.h"
#include "tetskin/spatial/TriangleIntersection.h"

namespace tetskin {
namespace {

Eigen::Vector3d position(const SurfaceMesh& m, int v) {
  return m.positions.row(v).transpose();
}

// Keeps the triangles whose flag is true.
void keepTriangles(SurfaceMesh& mesh, const std::vector<char>& keep) {
  Triangles kept(std::count(keep.begin(), keep.end(), 1), 3);
  Index next = 0;
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    if (keep[static_cast<std::size_t>(t)]) kept.row(next++) = mesh.triangles.row(t);
  mesh.triangles = std::move(kept);
}

// Whether triangle t traverses the edge as a -> b.
bool hasDirectedEdge(const SurfaceMesh& mesh, int t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (mesh.triangles(t, k) == a && mesh.triangles(t, (k + 1) % 3) == b) return true;
  return false;
}

void flip(SurfaceMesh& mesh, int t) {
  std::swap(mesh.triangles(t, 1), mesh.triangles(t, 2));
}

}  // namespace

Index weldVertices(SurfaceMesh& mesh, double tolerance) {
  const Index n = mesh.vertexCount();
  if (n == 0 || !(tolerance > 0)) return 0;
  // Hash grid with cells of the tolerance: a partner lies in one of 27 cells.
  struct CellHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
      return static_cast<std::size_t>(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
    }
  };
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<int>, CellHash> grid;
  grid.reserve(static_cast<std::size_t>(n));
  std::vector<int> representative(static_cast<std::size_t>(n));
  const double tol2 = tolerance * tolerance;
  Index merged = 0;
  for (Index v = 0; v < n; ++v) {
    const Eigen::Vector3d p = position(mesh, static_cast<int>(v));
    std::array<std::int64_t, 3> cell;
    for (int k = 0; k < 3; ++k) cell[k] = static_cast<std::int64_t>(std::floor(p[k] / tolerance));
    int found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it == grid.end()) continue;
          for (int u : it->second)
            if ((position(mesh, u) - p).squaredNorm() <= tol2) {
              found = u;
              break;
            }
        }
    if (found >= 0) {
      representative[static_cast<std::size_t>(v)] = found;
      ++merged;
    } else {
      representative[static_cast<std::size_t>(v)] = static_cast<int>(v);
      grid[cell].push_back(static_cast<int>(v));
    }
  }
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      mesh.triangles(t, k) = representative[static_cast<std::size_t>(mesh.triangles(t, k))];
  return merged;
}

Index removeDegenerateTriangles(SurfaceMesh& mesh, double areaTolerance) {
  std::vector<char> keep(static_cast<std::size_t>(mesh.triangleCount()), 1);
  Index removed = 0;
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    const int a = mesh.triangles(t, 0), b = mesh.triangles(t, 1), c = mesh.triangles(t, 2);
    const bool repeated = a == b || b == c || a == c;
    if (repeated ||
        !(triangleArea(position(mesh, a), position(mesh, b), position(mesh, c)) > areaTolerance)) {
      keep[static_cast<std::size_t>(t)] = 0;
      ++removed;
    }
  }
  if (removed) keepTriangles(mesh, keep);
  return removed;
}

Index removeDuplicateTriangles(SurfaceMesh& mesh) {
  struct KeyHash {
    std::size_t operator()(const std::array<int, 3>& k) const {
      return std::hash<std::uint64_t>()(edgeKey(k[0], k[1])) ^
             (static_cast<std::size_t>(k[2]) * 2654435761u);
    }
  };
  std::unordered_set<std::array<int, 3>, KeyHash> seen;
  std::vector<char> keep(static_cast<std::size_t>(mesh.triangleCount()), 1);
  Index removed = 0;
  for (Index t = 0; t < mesh.triangleCount(); ++t) {
    std::array<int, 3> key = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) {
      keep[static_cast<std::size_t>(t)] = 0;
      ++removed;
    }
  }
  if (removed) keepTriangles(mesh, keep);
  return removed;
}

OrientationResult orientConsistently(SurfaceMesh& mesh) {
  OrientationResult result;
  const SurfaceParts parts = surfaceParts(mesh);
  // Each triangle agrees with the one it was reached from (which is final
  // by then): across their shared edge a -> b, it traverses b -> a.
  auto sharedEdgeAgrees = [&](int t, int u) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      if (hasDirectedEdge(mesh, u, a, b)) return false;
      if (hasDirectedEdge(mesh, u, b, a)) return true;
    }
    return true;  // (no shared edge: cannot happen)
  };
  for (const auto& part : parts.triangles) {
    Index flipped = 0;
    for (int t : part)
      if (const int from = parts.reachedFrom[static_cast<std::size_t>(t)];
          from >= 0 && !sharedEdgeAgrees(t, from)) {
        flip(mesh, t);
        ++flipped;
      }
    // The part keeps the winding most of its triangles had.
    if (2 * flipped > static_cast<Index>(part.size())) {
      for (int t : part) flip(mesh, t);
      flipped = static_cast<Index>(part.size()) - flipped;
    }
    result.flippedTriangles += flipped;
  }
  // A manifold edge its two triangles traverse alike after that: a
  // Moebius-like part.
  for (const auto& [key, users] : edgeTriangles(mesh))
    if (users.size() == 2 && !sharedEdgeAgrees(users[0], users[1])) result.orientable = false;
  // An outermost part faces out, and the parts inside it turn with it: their
  // windings relative to it say where the cavities are (SurfaceNesting.h),
  // so a hollow ball wound inside out throughout stays hollow.
  const std::vector<std::vector<int>> enclosing = enclosingParts(mesh, parts.triangles);
  std::vector<char> inward;
  for (const auto& part : parts.triangles) inward.push_back(partVolume(mesh, part) < 0);
  for (std::size_t i = 0; i < parts.triangles.size(); ++i) {
    std::size_t outermost = i;
    for (int j : enclosing[i])
      if (enclosing[static_cast<std::size_t>(j)].empty()) outermost = static_cast<std::size_t>(j);
    if (!inward[outermost]) continue;
    for (int t : parts.triangles[i]) flip(mesh, t);
    ++result.invertedComponents;
  }
  const std::vector<char> cavity = cavityParts(mesh, parts.triangles, enclosing);
  result.cavities = std::count(cavity.begin(), cavity.end(), 1);
  return result;
}

std::vector<std::vector<int>> boundaryLoops(const SurfaceMesh& mesh) {
  const auto edges = edgeTriangles(mesh);
  std::unordered_map<int, std::vector<int>> neighbours;
  for (const auto& [key, users] : edges) {
    if (users.size() != 1) continue;
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  // One entry per connected chain of open edges, its vertices in walk order.
  std::vector<std::vector<int>> loops;
  std::unordered_set<int> visited;
  std::vector<int> starts;
  for (const auto& [v, n] : neighbours) starts.push_back(v);
  std::sort(starts.begin(), starts.end());  // deterministic order
  for (int start : starts) {
    if (visited.contains(start)) continue;
    std::vector<int> loop, stack = {start};
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (!visited.insert(v).second) continue;
      loop.push_back(v);
      for (int u : neighbours[v])
        if (!visited.contains(u)) stack.push_back(u);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

Index fillHoles(SurfaceMesh& mesh, double maxArea) {
  const auto edges = edgeTriangles(mesh);
  std::unordered_map<int, int> loopOf;  // rim vertex -> loop
  const std::vector<std::vector<int>> loops = boundaryLoops(mesh);
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (int v : loops[l]) loopOf[v] = static_cast<int>(l);
  // Each loop's open edges, directed as the fill must use them: the
  // reverse of their one triangle's direction.
  std::vector<std::vector<std::array<int, 2>>> rims(loops.size());
  for (const auto& [key, users] : edges) {
    if (users.size() != 1) continue;
    const Index t = users.front();
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      if (edgeKey(a, b) == key) rims[static_cast<std::size_t>(loopOf.at(a))].push_back({b, a});
    }
  }
  std::vector<Eigen::RowVector3d> centres;
  std::vector<std::array<int, 3>> fans;
  Index closed = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int v : loops[l]) centre += mesh.positions.row(v);
    centre /= static_cast<double>(loops[l].size());
    double area = 0;
    for (const auto& [a, b] : rims[l])
      area += 0.5 * (mesh.positions.row(a) - centre).cross(mesh.positions.row(b) - centre).norm();
    if (area > maxArea) continue;
    const int c = static_cast<int>(mesh.vertexCount() + static_cast<Index>(centres.size()));
    centres.push_back(centre);
    for (const auto& [a, b] : rims[l]) fans.push_back({a, b, c});
    ++closed;
  }
  if (closed == 0) return 0;
  const Index n = mesh.vertexCount(), m = mesh.triangleCount();
  mesh.positions.conservativeResize(n + static_cast<Index>(centres.size()), 3);
  for (std::size_t i = 0; i < centres.size(); ++i)
    mesh.positions.row(n + static_cast<Index>(i)) = centres[i];
  mesh.triangles.conservativeResize(m + static_cast<Index>(fans.size()), 3);
  for (std::size_t i = 0; i < fans.size(); ++i)
    for (int k = 0; k < 3; ++k) mesh.triangles(m + static_cast<Index>(i), k) = fans[i][k];
  mesh.normals.resize(0, 3);
  mesh.texcoords.resize(0, 2);
  return closed;
}

Index nonManifoldEdgeCount(const SurfaceMesh& mesh) {
  Index count = 0;
  for (const auto& [key, users] : edgeTriangles(mesh))
    if (users.size() > 2) ++count;
  return count;
}

Index splitTJunctions(SurfaceMesh& mesh, double tolerance) {
  if (!(tolerance > 0)) return 0;
  Index splits = 0;
  // One open edge per triangle is split per pass, fanned from the opposite
  // corner, so every new triangle is proper; a triangle with T-junctions on
  // two sides is split again in the next pass. (Each split makes a vertex
  // an end of the edges beside it, so the passes end; the cap guards
  // against a vertex a rounding keeps finding inside a shorter piece.)
  for (int pass = 0; pass < 64; ++pass) {
    struct OpenEdge {
      int triangle, corner;  // the edge runs from corner to corner + 1
    };
    std::vector<OpenEdge> open;
    std::vector<int> ends;
    for (const auto& [key, users] : edgeTriangles(mesh)) {
      if (users.size() != 1) continue;
      const int t = users[0];
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      for (int k = 0; k < 3; ++k)
        if (std::minmax(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3)) == std::minmax(a, b))
          open.push_back({t, k});
      ends.push_back(a);
      ends.push_back(b);
    }
    if (open.empty()) return splits;
    std::sort(open.begin(), open.end(), [](const OpenEdge& x, const OpenEdge& y) {
      return std::tie(x.triangle, x.corner) < std::tie(y.triangle, y.corner);
    });  // deterministic whatever the hash order
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::vector<Aabb> boxes(open.size());
    for (std::size_t e = 0; e < open.size(); ++e) {
      const auto& [t, k] = open[e];
      boxes[e].extend(position(mesh, mesh.triangles(t, k)));
      boxes[e].extend(position(mesh, mesh.triangles(t, (k + 1) % 3)));
      boxes[e] = boxes[e].inflated(tolerance);
    }
    const AabbTree tree(boxes);
    // For each open edge, the vertices strictly inside it, by where along it.
    std::vector<std::vector<std::pair<double, int>>> inside(open.size());
    for (int v : ends) {
      const Eigen::Vector3d p = position(mesh, v);
      Aabb point;
      point.extend(p);
      tree.forEachOverlap(point, [&](int e) {
        const auto& [t, k] = open[static_cast<std::size_t>(e)];
        const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
        if (v == a || v == b || v == mesh.triangles(t, (k + 2) % 3)) return;
        const Eigen::Vector3d pa = position(mesh, a), ab = position(mesh, b) - pa;
        const double length = ab.norm();
        const double along = (p - pa).dot(ab) / length;
        if (!(along > tolerance && along < length - tolerance)) return;
        if ((p - pa - along / length * ab).norm() > tolerance) return;
        inside[static_cast<std::size_t>(e)].emplace_back(along, v);
      });
    }
    std::vector<char> split(static_cast<std::size_t>(mesh.triangleCount()), 0);
    std::vector<Eigen::Vector3i> added;
    Index passSplits = 0;
    for (std::size_t e = 0; e < open.size(); ++e) {
      auto& on = inside[e];
      const auto& [t, k] = open[e];
      if (on.empty() || split[static_cast<std::size_t>(t)]) continue;
      split[static_cast<std::size_t>(t)] = 1;
      std::sort(on.begin(), on.end());
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3),
                c = mesh.triangles(t, (k + 2) % 3);
      int from = a;
      for (const auto& [along, v] : on) {
        if (v == from) continue;  // (one vertex listed twice)
        added.emplace_back(from, v, c);
        from = v;
        ++passSplits;
      }
      added.emplace_back(from, b, c);
    }
    if (passSplits == 0) return splits;
    splits += passSplits;
    std::vector<char> keep(split.size());
    for (std::size_t t = 0; t < split.size(); ++t) keep[t] = !split[t];
    keepTriangles(mesh, keep);
    const Index kept = mesh.triangleCount();
    mesh.triangles.conservativeResize(kept + static_cast<Index>(added.size()), 3);
    for (std::size_t i = 0; i < added.size(); ++i)
      mesh.triangles.row(kept + static_cast<Index>(i)) = added[i].transpose();
  }
  return splits;
}

namespace {

// Removes, round after round until none is left, the triangles for which
// `remove(users)` holds, `users` the number of triangles on each of its
// three edges. Returns the number removed.
template <typename Remove>
Index removeRepeatedly(SurfaceMesh& mesh, Remove remove) {
  Index removed = 0;
  for (;;) {
    const auto edges = edgeTriangles(mesh);
    std::vector<char> keep(static_cast<std::size_t>(mesh.triangleCount()), 1);
    Index round = 0;
    for (Index t = 0; t < mesh.triangleCount(); ++t) {
      std::array<std::size_t, 3> users{};
      for (int k = 0; k < 3; ++k)
        users[static_cast<std::size_t>(k)] =
            edges.at(edgeKey(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3))).size();
      if (remove(users)) {
        keep[static_cast<std::size_t>(t)] = 0;
        ++round;
      }
    }
    if (round == 0) return removed;
    keepTriangles(mesh, keep);
    removed += round;
  }
}

}  // namespace

Index removeFlaps(SurfaceMesh& mesh) {
  return removeRepeatedly(mesh, [](const std::array<std::size_t, 3>& users) {
    const bool open = std::find(users.begin(), users.end(), 1u) != users.end();
    const bool nonManifold =
        std::any_of(users.begin(), users.end(), [](std::size_t n) { return n > 2; });
    return open && nonManifold;
  });
}

Index removeOpenTriangles(SurfaceMesh& mesh) {
  return removeRepeatedly(mesh, [](const std::array<std::size_t, 3>& users) {
    return std::find(users.begin(), users.end(), 1u) != users.end();
  });
}

std::vector<std::pair<int, int>> findSelfIntersections(const SurfaceMesh& mesh, std::size_t limit) {
  const Index n = mesh.triangleCount();
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  for (Index t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      boxes[static_cast<std::size_t>(t)].extend(position(mesh, mesh.triangles(t, k)));
  const AabbTree tree(boxes);
  std::vector<std::pair<int, int>> pairs;
  for (Index t = 0; t < n && pairs.size() < limit; ++t) {
    const Eigen::Vector3d p[3] = {position(mesh, mesh.triangles(t, 0)),
                                  position(mesh, mesh.triangles(t, 1)),
                                  position(mesh, mesh.triangles(t, 2))};
    const int pid[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    tree.forEachOverlap(boxes[static_cast<std::size_t>(t)], [&](int u) {
      if (u <= t || pairs.size() >= limit) return;
      const Eigen::Vector3d q[3] = {position(mesh, mesh.triangles(u, 0)),
                                    position(mesh, mesh.triangles(u, 1)),
                                    position(mesh, mesh.triangles(u, 2))};
      const int qid[3] = {mesh.triangles(u, 0), mesh.triangles(u, 1), mesh.triangles(u, 2)};
      if (trianglesIntersect(p, pid, q, qid)) pairs.emplace_back(static_cast<int>(t), u);
    });
  }
  return pairs;
}

Index collapseIntersections(SurfaceMesh& mesh, const std::vector<std::pair<int, int>>& pairs) {
  const Index nv = mesh.vertexCount();
  std::vector<int> target(static_cast<std::size_t>(nv));
  for (Index v = 0; v < nv; ++v) target[static_cast<std::size_t>(v)] = static_cast<int>(v);
  std::vector<char> touched(static_cast<std::size_t>(nv), 0);
  // Collapsing triangle `from` onto `onto`: the vertex of `onto` nearest to
  // from's centroid, and the farthest any of from's vertices would move.
  struct Collapse {
    int from, point;
    double farthestMove;
  };
  auto collapse = [&](int from, int onto) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centroid += position(mesh, mesh.triangles(from, k)) / 3.0;
    int point = mesh.triangles(onto, 0);
    for (int k = 1; k < 3; ++k) {
      const int candidate = mesh.triangles(onto, k);
      if ((position(mesh, candidate) - centroid).squaredNorm() <
          (position(mesh, point) - centroid).squaredNorm())
        point = candidate;
    }
    double farthest = 0;
    for (int k = 0; k < 3; ++k)
      farthest = std::max(farthest,
                          (position(mesh, mesh.triangles(from, k)) - position(mesh, point)).norm());
    return Collapse{from, point, farthest};
  };
  Index collapsed = 0;
  for (const auto& [first, second] : pairs) {
    bool skip = false;
    for (int k = 0; k < 3; ++k)
      skip = skip || touched[static_cast<std::size_t>(mesh.triangles(first, k))] ||
             touched[static_cast<std::size_t>(mesh.triangles(second, k))];
    if (skip) continue;
    // The smaller change of shape: a small triangle poking through a large
    // one collapses onto it, not the large one onto the small one's corner.
    const Collapse forward = collapse(first, second), backward = collapse(second, first);
    const Collapse& chosen = backward.farthestMove < forward.farthestMove ? backward : forward;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(chosen.from, k);
      target[static_cast<std::size_t>(v)] = chosen.point;
      touched[static_cast<std::size_t>(v)] = 1;
    }
    touched[static_cast<std::size_t>(chosen.point)] = 1;
    ++collapsed;
  }
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      mesh.triangles(t, k) = target[static_cast<std::size_t>(mesh.triangles(t, k))];
  return collapsed;
}

Index removeUnusedVertices(SurfaceMesh& mesh) {
  const Index n = mesh.vertexCount();
  std::vector<int> newId(static_cast<std::size_t>(n), -1);
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) newId[static_cast<std::size_t>(mesh.triangles(t, k))] = 0;
  int next = 0;
  for (Index v = 0; v < n; ++v)
    if (newId[static_cast<std::size_t>(v)] == 0) newId[static_cast<std::size_t>(v)] = next++;
  if (next == n) return 0;
  auto compact = [&](auto& rows) {
    if (rows.rows() != n) return;
    std::remove_reference_t<decltype(rows)> kept(next, rows.cols());
    for (Index v = 0; v < n; ++v)
      if (newId[static_cast<std::size_t>(v)] >= 0)
        kept.row(newId[static_cast<std::size_t>(v)]) = rows.row(v);
    rows = std::move(kept);
  };
  compact(mesh.positions);
  compact(mesh.normals);
  compact(mesh.texcoords);
  for (Index t = 0; t < mesh.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      mesh.triangles(t, k) = newId[static_cast<std::size_t>(mesh.triangles(t, k))];
  return n - next;
}

std::vector<std::pair<std::string, Index>> RepairReport::counts() const {
  return {{"input_vertices", inputVertices},
          {"input_triangles", inputTriangles},
          {"welded_vertices", weldedVertices},
          {"degenerate_triangles", degenerateTriangles},
          {"duplicate_triangles", duplicateTriangles},
          {"flipped_triangles", flippedTriangles},
          {"inverted_components", invertedComponents},
          {"cavities", cavities},
          {"t_junctions_split", tJunctionsSplit},
          {"holes", holes},
          {"open_triangles_removed", openTrianglesRemoved},
          {"intersecting_pairs", intersectingPairs},
          {"collapsed_triangles", collapsedTriangles},
          {"intersection_rounds", intersectionRounds},
          {"unused_vertices", unusedVertices},
          {"output_vertices", outputVertices},
          {"output_triangles", outputTriangles}};
}

double RepairReport::collapseVolumeChange() const {
  if (intersectingPairs == 0 || volumeBeforeCollapse == 0) return 0;
  return (volumeAfterCollapse - volumeBeforeCollapse) / volumeBeforeCollapse;
}

std::string collapseWarning(const RepairReport& report, const std::string& name) {
  const double change = report.collapseVolumeChange();
  if (!(std::abs(change) > kCollapseVolumeTolerance)) return {};
  return name + ": collapsing " + std::to_string(report.intersectingPairs) +
         " intersecting pair(s) of triangles changed the enclosed volume by " +
         formatNumber(100 * change) + "% (" + formatNumber(report.volumeBeforeCollapse) + " to " +
         formatNumber(report.volumeAfterCollapse) +
         "); the collapse closes small defects, not overlapping parts: check the shape, or join "
         "the parts into one closed surface first";
}

RepairTolerances repairTolerances(const RepairOptions& options, double diagonal) {
  return {options.weldTolerance * diagonal, options.areaTolerance * diagonal * diagonal,
          options.tJunctionTolerance * diagonal};
}

void weldAndClean(SurfaceMesh& mesh, const RepairTolerances& tolerance, RepairReport& report) {
  report.weldedVertices += weldVertices(mesh, tolerance.weld);
  report.degenerateTriangles += removeDegenerateTriangles(mesh, tolerance.area);
  report.duplicateTriangles += removeDuplicateTriangles(mesh);
}

RepairReport repairSurface(SurfaceMesh& mesh, const std::string& name,
                           const RepairOptions& options) {
  validateSurface(mesh, name);
  RepairReport report;
  report.inputVertices = mesh.vertexCount();
  report.inputTriangles = mesh.triangleCount();
  mesh.normals.resize(0, 3);
  mesh.texcoords.resize(0, 2);
  if (mesh.triangleCount() == 0) throw Error(name, 0, "the surface has no triangles");
  const double diagonal = boundingBox(mesh).diagonal();
  if (!(diagonal > 0)) throw Error(name, 0, "the surface has zero extent");
  const RepairTolerances tolerance = repairTolerances(options, diagonal);

  weldAndClean(mesh, tolerance, report);
  if (mesh.triangleCount() == 0)
    throw Error(name, 0,
                "cannot be repaired: every triangle has zero area (its corners on one line or "
                "welded together), so the surface encloses nothing");
  report.tJunctionsSplit = splitTJunctions(mesh, tolerance.tJunction);
  report.holes = static_cast<Index>(boundaryLoops(mesh).size());
  report.openTrianglesRemoved = removeOpenTriangles(mesh);
  if (mesh.triangleCount() == 0)
    throw Error(name, 0,
                "cannot be repaired: the surface has " + std::to_string(report.holes) +
                    " hole(s) and removing triangles with open edges left nothing; close the "
                    "holes first");

  for (int round = 0;; ++round) {
    const auto pairs = findSelfIntersections(mesh);
    if (round == 0) report.intersectingPairs = static_cast<Index>(pairs.size());
    if (pairs.empty()) break;
    if (round == 0) {  // (orientation comes last, so a copy is oriented to measure)
      SurfaceMesh oriented = mesh;
      orientConsistently(oriented);
      report.volumeBeforeCollapse = enclosedVolume(oriented);
    }
    if (round == options.maxIntersectionRounds)
      throw Error(name, 0,
                  "cannot be repaired: " + std::to_string(pairs.size()) +
                      " pair(s) of triangles still intersect after " + std::to_string(round) +
                      " collapse rounds (first: triangles " + std::to_string(pairs[0].first) +
                      " and " + std::to_string(pairs[0].second) + ")");
    report.collapsedTriangles += collapseIntersections(mesh, pairs);
    report.intersectionRounds = round + 1;
    weldAndClean(mesh, tolerance, report);
    report.openTrianglesRemoved += removeOpenTriangles(mesh);
    if (mesh.triangleCount() == 0)
      throw Error(name, 0, "cannot be repaired: collapsing intersections left nothing");
  }
  const OrientationResult orientation = orientConsistently(mesh);
  report.flippedTriangles = orientation.flippedTriangles;
  report.invertedComponents = orientation.invertedComponents;
  report.cavities = orientation.cavities;
  if (!orientation.orientable)
    throw Error(name, 0, "cannot be repaired: the surface is not orientable");
  report.unusedVertices = removeUnusedVertices(mesh);
  if (report.intersectingPairs > 0) report.volumeAfterCollapse = enclosedVolume(mesh);
  report.outputVertices = mesh.vertexCount();
  report.outputTriangles = mesh.triangleCount();
  return report;
}

}  // namespace tetskin
