// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/binding/BindSurface.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/spatial/AabbTree.h"
#include "tetskin/spatial/TetLocator.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One candidate face for a surface vertex, with what the choice depends on.
struct Choice {
  int face = -1;           // index into the usable faces
  bool agrees = false;     // face normal points the way the surface normal does
  double minBary = -kInf;  // smallest plane barycentric coordinate
  double squaredDistance = kInf;
  Eigen::Vector3d bary = Eigen::Vector3d::Zero();
  double signedDistance = 0;
};

// The tie-break of the Closest method, a strict total order.
bool better(const Choice& a, const Choice& b) {
  if (a.agrees != b.agrees) return a.agrees;
  if (a.minBary != b.minBary) return a.minBary > b.minBary;
  if (a.squaredDistance != b.squaredDistance) return a.squaredDistance < b.squaredDistance;
  return a.face < b.face;
}

// The chosen level and where its nodes and elements are in the dataset:
// what every method needs.
struct BoundLevel {
  TetMesh mesh;        // level-local numbering
  int nodeOffset = 0;  // level-local + offset = dataset numbering
  int elementOffset = 0;
};

BoundLevel boundLevel(const MultiLevelTetMesh& mesh, int level) {
  BoundLevel bound;
  bound.mesh = extractLevel(mesh, level);
  const LevelRange& range = mesh.levels[static_cast<std::size_t>(level)];
  bound.nodeOffset = static_cast<int>(range.firstNode);
  bound.elementOffset = static_cast<int>(range.firstElement);
  validateTetMesh(bound.mesh, "level " + std::to_string(level), /*requirePositiveVolume=*/false);
  return bound;
}

// The level's boundary: what the triangle methods (closest, seed) need.
struct ControlSurface {
  BoundLevel level;
  Triangles faces;            // usable (non-degenerate) boundary faces, level-local ids
  std::vector<int> elements;  // per usable face: its element, level-local
  Points3 unitNormals;        // per usable face
  double diagonal = 0;
  double meanEdge = 0;  // of the usable faces
  Index degenerateFaces = 0;

  Eigen::Vector3d corner(int face, int k) const {
    return level.mesh.nodes.row(faces(face, k)).transpose();
  }
};

ControlSurface controlSurface(BoundLevel bound, int level) {
  ControlSurface cs;
  cs.level = std::move(bound);
  const BoundaryFaces all = boundaryFaces(cs.level.mesh);
  cs.diagonal = boundingBox(cs.level.mesh.nodes).diagonal();
  std::vector<Index> usable;
  for (Index f = 0; f < all.faces.rows(); ++f) {
    const Eigen::Vector3d a = cs.level.mesh.nodes.row(all.faces(f, 0)),
                          b = cs.level.mesh.nodes.row(all.faces(f, 1)),
                          c = cs.level.mesh.nodes.row(all.faces(f, 2));
    // Zero-area faces have no plane: skip them (their neighbours cover the spot).
    if (triangleArea(a, b, c) > 1e-14 * cs.diagonal * cs.diagonal)
      usable.push_back(f);
    else
      ++cs.degenerateFaces;
  }
  if (usable.empty())
    throw Error("level " + std::to_string(level) + " has no usable boundary faces");
  cs.faces.resize(static_cast<Index>(usable.size()), 3);
  cs.unitNormals.resize(static_cast<Index>(usable.size()), 3);
  for (std::size_t i = 0; i < usable.size(); ++i) {
    cs.faces.row(static_cast<Index>(i)) = all.faces.row(usable[i]);
    cs.elements.push_back(all.elements[static_cast<std::size_t>(usable[i])]);
    const Eigen::Vector3d a = cs.corner(static_cast<int>(i), 0),
                          b = cs.corner(static_cast<int>(i), 1),
                          c = cs.corner(static_cast<int>(i), 2);
    cs.unitNormals.row(static_cast<Index>(i)) = triangleNormal(a, b, c).transpose();
    cs.meanEdge += ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
  }
  cs.meanEdge /= static_cast<double>(usable.size());
  return cs;
}

Choice evaluate(const ControlSurface& cs, int face, const Eigen::Vector3d& p,
                const Eigen::Vector3d& surfaceNormal) {
  const Eigen::Vector3d a = cs.corner(face, 0), b = cs.corner(face, 1), c = cs.corner(face, 2);
  const Eigen::Vector3d n = cs.unitNormals.row(face).transpose();
  Choice choice;
  choice.face = face;
  choice.squaredDistance = closestPointOnTriangle(p, a, b, c).squaredDistance;
  choice.bary = planeBarycentric(p, a, b, c);
  choice.minBary = choice.bary.minCoeff();
  choice.signedDistance = n.dot(p - a);
  choice.agrees = n.dot(surfaceNormal) > 0;
  return choice;
}

void store(const ControlSurface& cs, const Choice& choice, Index v, SurfaceBinding& out) {
  for (int k = 0; k < 3; ++k) {
    out.controlIds(v, k) = cs.faces(choice.face, k) + cs.level.nodeOffset;
    out.weights(v, k) = choice.bary[k];
  }
  out.controlIds(v, 3) = -1;  // (a triangle's three)
  out.weights(v, 3) = 0;
  out.distance[v] = choice.signedDistance;
  // (The element of the face, in the dataset's numbering: FaceId's one
  // numbering, SurfaceBinding.h.)
  out.faceId[v] = cs.elements[static_cast<std::size_t>(choice.face)] + cs.level.elementOffset;
  out.minBarycentric[v] = choice.minBary;
}

void checkSurface(const SurfaceMesh& surface) {
  if (surface.vertexCount() == 0) throw Error("the surface to bind has no vertices");
  validateSurface(surface, "surface");
}

template <typename PerVertex>
void forEachVertex(Index n, PerVertex&& f) {
  parallelFor<Index>(0, n, 256, [&](const IndexRange<Index>& r) {
    for (Index v = r.begin(); v != r.end(); ++v) f(v);
  });
}

SurfaceBinding emptyBinding(const SurfaceMesh& surface, const BindingOptions& options, int level) {
  SurfaceBinding b;
  b.method = options.method;
  b.offset = options.offset;
  b.level = level;
  // Left uninitialized: every method writes each vertex's every field in
  // its parallel pass, which so touches the pages first (at 33M vertices
  // 2.2 GB, which a serial fill took seconds to fault in).
  const Index n = surface.vertexCount();
  b.controlIds.resize(n, 4);
  b.weights.resize(n, 4);
  b.distance.resize(n);
  b.faceId.resize(n);
  b.minBarycentric.resize(n);
  return b;
}

// The chosen face among `faces` within `limit2` (squared) of p: the
// tie-break's best.
template <typename Faces>
Choice choose(const ControlSurface& cs, const Faces& faces, double limit2, const Eigen::Vector3d& p,
              const Eigen::Vector3d& np) {
  Choice chosen;
  for (const auto& [f, d2] : faces)
    if (d2 <= limit2) {
      const Choice c = evaluate(cs, f, p, np);
      if (chosen.face < 0 || better(c, chosen)) chosen = c;
    }
  return chosen;
}

double squared(double x) {
  return x * x;
}

// The faces within the tie tolerance of the nearest to a point, gathered
// one face at a time (from the tree, or from faces kept near a vertex
// before): `limit2` shrinks to the nearest squared distance so far plus the
// tolerance, squared, and a face beyond it is not kept; finish() drops the
// faces kept before the limit shrank past them.
struct NearestFaces {
  explicit NearestFaces(double tieTolerance) : tolerance(tieTolerance) {}

  const double tolerance;
  std::vector<std::pair<int, double>> faces;  // (face, squared distance)
  double best2 = kInf, limit2 = kInf;

  void clear() {
    faces.clear();
    best2 = limit2 = kInf;
  }
  void keep(int f, double d2) {
    if (d2 > limit2) return;
    faces.emplace_back(f, d2);
    if (d2 < best2) {
      best2 = d2;
      limit2 = squared(std::sqrt(d2) + tolerance);
    }
  }
  void finish() {
    std::erase_if(faces, [&](const std::pair<int, double>& face) { return face.second > limit2; });
  }
};

SurfaceBinding bindClosest(const SurfaceMesh& surface, const ControlSurface& cs,
                           const BindingOptions& options, int level, bool bruteForce) {
  SurfaceBinding out = emptyBinding(surface, options, level);
  const double tolerance = options.tieTolerance * cs.diagonal;
  const auto distance2 = [&](int f, const Eigen::Vector3d& p) {
    return closestPointOnTriangle(p, cs.corner(f, 0), cs.corner(f, 1), cs.corner(f, 2))
        .squaredDistance;
  };
  if (bruteForce) {  // (the reference the tree's search is tested against)
    const Points3 normals = vertexNormals(surface.positions, surface.triangles);
    forEachVertex(surface.vertexCount(), [&](Index v) {
      const Eigen::Vector3d p = surface.positions.row(v).transpose();
      std::vector<std::pair<int, double>> faces;
      double best2 = kInf;
      for (int f = 0; f < cs.faces.rows(); ++f) {
        faces.emplace_back(f, distance2(f, p));
        best2 = std::min(best2, faces.back().second);
      }
      store(cs,
            choose(cs, faces, squared(std::sqrt(best2) + tolerance), p, normals.row(v).transpose()),
            v, out);
    });
    return out;
  }
  std::vector<Aabb> boxes(static_cast<std::size_t>(cs.faces.rows()));
  for (Index f = 0; f < cs.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      boxes[static_cast<std::size_t>(f)].extend(cs.corner(static_cast<int>(f), k));
  const AabbTree tree(boxes);
  // One pass of the tree for point p: the faces within the tie tolerance of
  // the nearest into `near`. Its radius is the shrinking limit, and every
  // face within it when visited is kept, so the faces within the tolerance
  // of the nearest (none of which the shrinking radius ever cuts off) are
  // among them. It starts from `start` (the face chosen for the vertex
  // before: the surface's neighbours are mostly numbered near each other),
  // whose distance bounds the nearest from the start.
  const auto searchTree = [&](const Eigen::Vector3d& p, int start, NearestFaces& near) {
    near.clear();
    if (start >= 0) near.keep(start, distance2(start, p));
    double radius2 = near.limit2;
    tree.forEachNear(p, radius2, [&](int f, double& r2) {
      if (f == start) return;
      near.keep(f, distance2(f, p));
      r2 = near.limit2;
    });
    near.finish();
  };
  // A vertex with one face within the tolerance takes it. Where several
  // are, the tie-break asks the surface's normal there: those vertices
  // (few) are bound after the pass, with the normals of theirs alone, not
  // every vertex's (at 33M vertices the adjacency and normals took
  // gigabytes and seconds).
  std::vector<Index> tied;
  std::mutex tiedMutex;
  // How far past a vertex's tie limit the faces kept for the vertices after
  // it reach: half a boundary edge (on bunny_64k Loop x3, 97% of the
  // vertices then found their faces there; a quarter or a whole edge, 91%
  // and 99%, were slower: fewer hits, or more faces a hit).
  const double reach = 0.5 * cs.meanEdge;
  parallelFor<Index>(0, surface.vertexCount(), 256, [&](const IndexRange<Index>& range) {
    NearestFaces near(tolerance);  // reused
    std::vector<Index> tiedHere;
    int previous = -1;
    // The faces within `radius` of `center`, a vertex met before, all of
    // them: a vertex p whose faces within its tie limit lie inside that
    // ball (|p - center| + limit <= radius) finds them there, without the
    // tree. Neighbours on the surface are mostly numbered near each
    // other, so most vertices do.
    struct {
      Eigen::Vector3d center = Eigen::Vector3d::Zero();
      double radius = -1;
      std::vector<int> faces;
    } ball;
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Vector3d p = surface.positions.row(v).transpose();
      bool found = false;
      if (ball.radius > 0) {
        near.clear();
        for (int f : ball.faces)
          // (A face whose box lies beyond the limit so far is beyond it.)
          if (boxes[static_cast<std::size_t>(f)].squaredDistance(p) <= near.limit2)
            near.keep(f, distance2(f, p));
        // (With a margin for the rounding of the three distances.)
        found = (p - ball.center).norm() + std::sqrt(near.limit2) <= ball.radius * (1 - 1e-9);
        if (found) near.finish();
      }
      if (!found) {
        searchTree(p, previous, near);
        ball.center = p;
        ball.radius = std::sqrt(near.limit2) + reach;
        ball.faces.clear();
        double radius2 = squared(ball.radius);
        tree.forEachNear(p, radius2, [&](int f, double& r2) {
          if (distance2(f, p) <= r2) ball.faces.push_back(f);
        });
      }
      if (near.faces.size() == 1) {
        const Choice chosen = choose(cs, near.faces, near.limit2, p, Eigen::Vector3d::Zero());
        store(cs, chosen, v, out);
        previous = chosen.face;
      } else {
        tiedHere.push_back(v);
        previous =
            std::min_element(near.faces.begin(), near.faces.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; })
                ->first;
      }
    }
    if (tiedHere.empty()) return;
    const std::lock_guard<std::mutex> lock(tiedMutex);
    tied.insert(tied.end(), tiedHere.begin(), tiedHere.end());
  });
  std::sort(tied.begin(), tied.end());
  const Points3 tiedNormals = vertexNormalsOf(surface.positions, surface.triangles, tied);
  parallelFor<Index>(0, static_cast<Index>(tied.size()), 64, [&](const IndexRange<Index>& range) {
    NearestFaces near(tolerance);
    for (Index i = range.begin(); i != range.end(); ++i) {
      const Index v = tied[static_cast<std::size_t>(i)];
      const Eigen::Vector3d p = surface.positions.row(v).transpose();
      searchTree(p, -1, near);
      store(cs, choose(cs, near.faces, near.limit2, p, tiedNormals.row(i).transpose()), v, out);
    }
  });
  return out;
}

// The report's method as written: score = smallest plane barycentric minus
// the plane distance over the mean boundary edge length, searched among the
// faces of the vertex's octant around the centroid.
SurfaceBinding bindSeed(const SurfaceMesh& surface, const ControlSurface& cs,
                        const BindingOptions& options, int level) {
  SurfaceBinding out = emptyBinding(surface, options, level);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double edgeSum = 0;
  for (Index f = 0; f < cs.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      centroid += cs.corner(static_cast<int>(f), k);
      edgeSum +=
          (cs.corner(static_cast<int>(f), k) - cs.corner(static_cast<int>(f), (k + 1) % 3)).norm();
    }
  centroid /= 3.0 * static_cast<double>(cs.faces.rows());
  const double meanEdge = edgeSum / (3.0 * static_cast<double>(cs.faces.rows()));
  std::array<std::vector<int>, 8> octants;
  for (Index f = 0; f < cs.faces.rows(); ++f) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.extend(cs.corner(static_cast<int>(f), k));
    for (int o = 0; o < 8; ++o) {
      bool touches = true;
      for (int axis = 0; axis < 3; ++axis) {
        const bool upper = (o >> axis) & 1;
        touches =
            touches && (upper ? box.max[axis] >= centroid[axis] : box.min[axis] <= centroid[axis]);
      }
      if (touches) octants[static_cast<std::size_t>(o)].push_back(static_cast<int>(f));
    }
  }
  const Points3 normals = vertexNormals(surface.positions, surface.triangles);
  forEachVertex(surface.vertexCount(), [&](Index v) {
    const Eigen::Vector3d p = surface.positions.row(v).transpose();
    int o = 0;
    for (int axis = 0; axis < 3; ++axis) o |= (p[axis] >= centroid[axis] ? 1 : 0) << axis;
    const std::vector<int>& faces = octants[static_cast<std::size_t>(o)];
    Choice chosen;
    double bestScore = -kInf;
    for (int f : faces) {
      const Choice c = evaluate(cs, f, p, normals.row(v).transpose());
      const double score = c.minBary - std::abs(c.signedDistance) / meanEdge;
      if (score > bestScore) {
        bestScore = score;
        chosen = c;
      }
    }
    if (chosen.face < 0) chosen = evaluate(cs, 0, p, normals.row(v).transpose());
    store(cs, chosen, v, out);
  });
  return out;
}

// SOFA/VegaFEM-style embedding: the containing element's 4 barycentric
// weights; outside the volume the nearest element, extrapolated.
SurfaceBinding bindEmbed(const SurfaceMesh& surface, const BoundLevel& bound,
                         const BindingOptions& options, int level) {
  SurfaceBinding out = emptyBinding(surface, options, level);
  const TetMesh& m = bound.mesh;
  const TetLocator locator(m);
  forEachVertex(surface.vertexCount(), [&](Index v) {
    const TetLocation at = locator.locate(surface.positions.row(v).transpose());
    for (int k = 0; k < 4; ++k) {
      out.controlIds(v, k) = m.elements(at.element, k) + bound.nodeOffset;
      out.weights(v, k) = at.barycentric[k];
    }
    out.distance[v] = std::sqrt(at.squaredDistance);
    out.faceId[v] = at.element + bound.elementOffset;
    out.minBarycentric[v] = at.barycentric.minCoeff();
  });
  return out;
}

}  // namespace

SurfaceBinding bindSurface(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh, int level,
                           const BindingOptions& options) {
  checkSurface(surface);
  if (level < 0) level = mesh.finestLevel();
  BoundLevel bound = boundLevel(mesh, level);
  // (Embed needs no boundary.)
  if (options.method == BindingMethod::Embed) return bindEmbed(surface, bound, options, level);
  const ControlSurface cs = controlSurface(std::move(bound), level);
  switch (options.method) {
    case BindingMethod::Closest:
      return bindClosest(surface, cs, options, level, false);
    case BindingMethod::Seed:
      return bindSeed(surface, cs, options, level);
    case BindingMethod::Embed:
      break;
  }
  throw Error("unknown binding method");
}

SurfaceBinding bindClosestBruteForce(const SurfaceMesh& surface, const MultiLevelTetMesh& mesh,
                                     int level, const BindingOptions& options) {
  checkSurface(surface);
  if (level < 0) level = mesh.finestLevel();
  BindingOptions closest = options;
  closest.method = BindingMethod::Closest;
  return bindClosest(surface, controlSurface(boundLevel(mesh, level), level), closest, level, true);
}

}  // namespace tetskin
