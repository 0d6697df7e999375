// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/spatial/TriangleDistance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

namespace tetskin {

ClosestPointOnTriangle closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  ClosestPointOnTriangle r;
  auto finish = [&](double u, double v, double w) {
    r.barycentric = {u, v, w};
    r.point = u * a + v * b + w * c;
    r.squaredDistance = (p - r.point).squaredNorm();
    return r;
  };
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0);  // vertex region a
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0);  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {  // edge region ab
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1);  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {  // edge region ac
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {  // edge region bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) {
    // Degenerate triangle (zero area): fall back to the nearest of its edges.
    ClosestPointOnTriangle best;
    best.squaredDistance = std::numeric_limits<double>::infinity();
    const Eigen::Vector3d* v[3] = {&a, &b, &c};
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& s = *v[e];
      const Eigen::Vector3d& t = *v[(e + 1) % 3];
      const double len2 = (t - s).squaredNorm();
      const double u = len2 > 0 ? std::clamp((p - s).dot(t - s) / len2, 0.0, 1.0) : 0.0;
      const Eigen::Vector3d q = s + u * (t - s);
      const double d = (p - q).squaredNorm();
      if (d < best.squaredDistance) {
        best.squaredDistance = d;
        best.point = q;
        best.barycentric.setZero();
        best.barycentric[e] = 1 - u;
        best.barycentric[(e + 1) % 3] += u;
      }
    }
    return best;
  }
  const double denom = 1.0 / sum;
  const double v = vb * denom, w = vc * denom;
  return finish(1 - v - w, v, w);  // face region
}

Eigen::Vector3d planeBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  const double u = (c - b).cross(p - b).dot(n) / n2;
  const double v = (a - c).cross(p - c).dot(n) / n2;
  return {u, v, 1.0 - u - v};
}

TriangleFeature closestFeature(const Eigen::Vector3d& barycentric) {
  int zeros = 0, zero = -1, nonzero = -1;
  for (int k = 0; k < 3; ++k)
    if (barycentric[k] == 0) {
      ++zeros;
      zero = k;
    } else {
      nonzero = k;
    }
  if (zeros == 2) return {TriangleFeature::Corner, nonzero};
  if (zeros == 1) return {TriangleFeature::Edge, zero};
  return {};
}

}  // namespace tetskin
