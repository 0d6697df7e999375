// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/TriangleIntersection.h"

#include <Eigen/Geometry>

#include "ExactPredicates.h"

namespace tetskin {
namespace {

using V3 = Eigen::Vector3d;
using V2 = Eigen::Vector2d;

// Which side of plane abc d lies on, and which way a 2D turn goes: exact
// signs (ExactPredicates.h).
int orient3d(const V3& a, const V3& b, const V3& c, const V3& d) {
  return orientation3d(a, b, c, d);
}
int orient2d(const V2& a, const V2& b, const V2& c) {
  return orientation2d(a, b, c);
}

// Closed segments s and t in 2D intersect (touching counts).
bool segmentsIntersect2d(const V2& s0, const V2& s1, const V2& t0, const V2& t1) {
  const int o1 = orient2d(s0, s1, t0), o2 = orient2d(s0, s1, t1);
  const int o3 = orient2d(t0, t1, s0), o4 = orient2d(t0, t1, s1);
  if (o1 != o2 && o3 != o4) return true;
  auto onSegment = [](const V2& a, const V2& b, const V2& p) {
    return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) &&
           p.y() >= std::min(a.y(), b.y()) && p.y() <= std::max(a.y(), b.y());
  };
  return (o1 == 0 && onSegment(s0, s1, t0)) || (o2 == 0 && onSegment(s0, s1, t1)) ||
         (o3 == 0 && onSegment(t0, t1, s0)) || (o4 == 0 && onSegment(t0, t1, s1));
}

// Point strictly inside triangle (2D).
bool insideTriangle2d(const V2& p, const V2 (&t)[3]) {
  const int a = orient2d(t[0], t[1], p), b = orient2d(t[1], t[2], p), c = orient2d(t[2], t[0], p);
  return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
}

bool segmentTriangle2d(const V2& s0, const V2& s1, const V2 (&t)[3]) {
  if (insideTriangle2d(s0, t) || insideTriangle2d(s1, t)) return true;
  for (int e = 0; e < 3; ++e)
    if (segmentsIntersect2d(s0, s1, t[e], t[(e + 1) % 3])) return true;
  return false;
}

// Closed segment (s0, s1) meets triangle t (non-coplanar case; touching counts).
bool segmentTriangle3d(const V3& s0, const V3& s1, const V3 (&t)[3]) {
  const int d0 = orient3d(t[0], t[1], t[2], s0), d1 = orient3d(t[0], t[1], t[2], s1);
  if (d0 == 0 && d1 == 0) return false;  // coplanar: handled by the 2D path
  if (d0 * d1 > 0) return false;
  const int e0 = orient3d(s0, s1, t[0], t[1]), e1 = orient3d(s0, s1, t[1], t[2]),
            e2 = orient3d(s0, s1, t[2], t[0]);
  return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

// Drops the coordinate along which the normal is largest.
struct Projection {
  int x, y;
  explicit Projection(const V3& n) {
    int drop = 0;
    n.cwiseAbs().maxCoeff(&drop);
    x = (drop + 1) % 3;
    y = (drop + 2) % 3;
  }
  V2 operator()(const V3& p) const { return {p[x], p[y]}; }
};

bool coplanar(const V3 (&p)[3], const V3 (&q)[3]) {
  for (const V3& v : q)
    if (orient3d(p[0], p[1], p[2], v) != 0) return false;
  return true;
}

bool disjointIntersect(const V3 (&p)[3], const V3 (&q)[3]) {
  if (coplanar(p, q)) {
    const Projection proj((p[1] - p[0]).cross(p[2] - p[0]));
    const V2 p2[3] = {proj(p[0]), proj(p[1]), proj(p[2])};
    const V2 q2[3] = {proj(q[0]), proj(q[1]), proj(q[2])};
    for (int e = 0; e < 3; ++e)
      if (segmentTriangle2d(q2[e], q2[(e + 1) % 3], p2)) return true;
    return insideTriangle2d(p2[0], q2);
  }
  for (int e = 0; e < 3; ++e) {
    if (segmentTriangle3d(p[e], p[(e + 1) % 3], q)) return true;
    if (segmentTriangle3d(q[e], q[(e + 1) % 3], p)) return true;
  }
  return false;
}

// Rotates the corners so the shared vertex comes first.
void rotateToFront(V3 (&t)[3], int k) {
  if (k == 1) {
    const V3 a = t[0];
    t[0] = t[1];
    t[1] = t[2];
    t[2] = a;
  } else if (k == 2) {
    const V3 a = t[2];
    t[2] = t[1];
    t[1] = t[0];
    t[0] = a;
  }
}

bool sharedVertexIntersect(V3 (&p)[3], int pk, V3 (&q)[3], int qk) {
  rotateToFront(p, pk);
  rotateToFront(q, qk);
  if (coplanar(p, q)) {
    const Projection proj((p[1] - p[0]).cross(p[2] - p[0]));
    const V2 p2[3] = {proj(p[0]), proj(p[1]), proj(p[2])};
    const V2 q2[3] = {proj(q[0]), proj(q[1]), proj(q[2])};
    if (segmentTriangle2d(p2[1], p2[2], q2) || segmentTriangle2d(q2[1], q2[2], p2)) return true;
    // The wedges at the shared vertex o overlap when an edge of one enters
    // the other: d strictly between e1 and e2 (the corners' far ends).
    auto inWedge = [](const V2& o, const V2& d, const V2& e1, const V2& e2) {
      const int w = orient2d(o, e1, e2);
      return w != 0 && orient2d(o, e1, d) == w && orient2d(o, d, e2) == w;
    };
    const V2& o = p2[0];  // (q2[0], the same vertex)
    return inWedge(o, p2[1], q2[1], q2[2]) || inWedge(o, p2[2], q2[1], q2[2]) ||
           inWedge(o, q2[1], p2[1], p2[2]) || inWedge(o, q2[2], p2[1], p2[2]);
  }
  return segmentTriangle3d(p[1], p[2], q) || segmentTriangle3d(q[1], q[2], p);
}

bool sharedEdgeIntersect(const V3 (&p)[3], int pOpposite, const V3 (&q)[3], int qOpposite,
                         const V3& e0, const V3& e1) {
  // Non-coplanar triangles meet only along the common line, i.e. the shared edge.
  if (orient3d(p[0], p[1], p[2], q[qOpposite]) != 0) return false;
  // Coplanar: they overlap when both lie on the same side of the shared edge.
  const Projection proj((p[1] - p[0]).cross(p[2] - p[0]));
  return orient2d(proj(e0), proj(e1), proj(p[pOpposite])) ==
         orient2d(proj(e0), proj(e1), proj(q[qOpposite]));
}

}  // namespace

bool trianglesIntersect(const Eigen::Vector3d (&p)[3], const int (&pid)[3],
                        const Eigen::Vector3d (&q)[3], const int (&qid)[3]) {
  int shared = 0, pk = -1, qk = -1;
  bool pShared[3] = {false, false, false}, qShared[3] = {false, false, false};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (pid[i] == qid[j]) {
        ++shared;
        pShared[i] = qShared[j] = true;
        pk = i;
        qk = j;
      }
  if (shared >= 3) return false;  // duplicates are the repair's business, not an intersection
  V3 pc[3] = {p[0], p[1], p[2]}, qc[3] = {q[0], q[1], q[2]};
  if (shared == 0) return disjointIntersect(p, q);
  if (shared == 1) return sharedVertexIntersect(pc, pk, qc, qk);
  int pOpposite = 0, qOpposite = 0;
  for (int i = 0; i < 3; ++i) {
    if (!pShared[i]) pOpposite = i;
    if (!qShared[i]) qOpposite = i;
  }
  const V3& e0 = p[(pOpposite + 1) % 3];
  const V3& e1 = p[(pOpposite + 2) % 3];
  return sharedEdgeIntersect(p, pOpposite, q, qOpposite, e0, e1);
}

}  // namespace tetskin
