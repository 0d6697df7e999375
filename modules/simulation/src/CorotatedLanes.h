// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The corotated element pass's arithmetic, written once for a "lane" type:
// double for one element (the scalar rotation(F, q), its fallbacks) or a
// GCC vector of four doubles for four elements at once (the element pass,
// compiled for AVX2/FMA and for the baseline, SimdKernel.h). The same
// expressions work for both because GCC's vector extension broadcasts
// scalars, compares lane by lane into masks and selects with ?:. Matrices
// are nine lanes each, row-major; nothing here knows Eigen, so the AVX2
// version compiles no Eigen code under another target.

#include <cmath>

// Four-double vectors passed by value change the ABI between AVX and
// baseline code, which GCC warns of; every function here is always inlined,
// so no call passes one.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tetskin::lanes {

using Double4 = double __attribute__((vector_size(32)));
using Mask4 = long __attribute__((vector_size(32)));  // a comparison of Double4s

#define TETSKIN_LANES_INLINE inline __attribute__((always_inline))

TETSKIN_LANES_INLINE bool any(bool m) {
  return m;
}
TETSKIN_LANES_INLINE bool any(Mask4 m) {
  return (m[0] | m[1] | m[2] | m[3]) != 0;
}
TETSKIN_LANES_INLINE double sqrtLanes(double v) {
  return std::sqrt(v);
}
TETSKIN_LANES_INLINE Double4 sqrtLanes(Double4 v) {
  // Lane by lane (GCC has no generic vector square root; three per element).
  for (int l = 0; l < 4; ++l) v[l] = __builtin_sqrt(v[l]);
  return v;
}
TETSKIN_LANES_INLINE double absLanes(double v) {
  return std::abs(v);
}
TETSKIN_LANES_INLINE Double4 absLanes(Double4 v) {
  return v < 0 ? -v : v;
}
// The mask type of a lane type (what a comparison gives).
template <typename V>
using MaskOf = decltype(V{} < V{});
template <typename V>
TETSKIN_LANES_INLINE MaskOf<V> noLanes() {
  return V{} != V{};
}

template <typename V>
struct Quaternion {
  V w, x, y, z;
};

// The rotation matrix of a unit quaternion (row-major), as Eigen computes it.
template <typename V>
TETSKIN_LANES_INLINE void rotationMatrix(const Quaternion<V>& q, V R[9]) {
  const V tx = 2 * q.x, ty = 2 * q.y, tz = 2 * q.z;
  const V twx = tx * q.w, twy = ty * q.w, twz = tz * q.w;
  const V txx = tx * q.x, txy = ty * q.x, txz = tz * q.x;
  const V tyy = ty * q.y, tyz = tz * q.y, tzz = tz * q.z;
  R[0] = 1 - (tyy + tzz);
  R[1] = txy - twz;
  R[2] = txz + twy;
  R[3] = txy + twz;
  R[4] = 1 - (txx + tzz);
  R[5] = tyz - twx;
  R[6] = txz - twy;
  R[7] = tyz + twx;
  R[8] = 1 - (txx + tyy);
}

// One step of the polar decomposition's Newton iteration (CorotatedFem.h):
// maximize trace(R^T A) over R exp([w]x), R = R(q). With S = R^T A the
// gradient is s = axial(S - S^T) and the Hessian H = trace(S) I - sym(S);
// Newton's step solves H w = s (quadratic convergence; Müller et al. divide
// by trace(S) alone, which converges linearly). Where H is not safely
// positive definite (far from the maximum) the step is their gradient step
// and the lane's result is false. Writes R(q) and the step.
template <typename V>
TETSKIN_LANES_INLINE MaskOf<V> rotationStep(const Quaternion<V>& q, const V A[9], V R[9],
                                            V step[3]) {
  rotationMatrix(q, R);
  V S[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      S[3 * i + j] = R[i] * A[j] + R[3 + i] * A[3 + j] + R[6 + i] * A[6 + j];
  const V s0 = S[7] - S[5], s1 = S[2] - S[6], s2 = S[3] - S[1];
  const V trace = S[0] + S[4] + S[8];
  // H = trace I - sym(S); symmetric, so its inverse from cofactors, and
  // positive definite when its leading minors are (Sylvester).
  const V h00 = trace - S[0], h11 = trace - S[4], h22 = trace - S[8];
  const V h01 = -0.5 * (S[1] + S[3]), h02 = -0.5 * (S[2] + S[6]), h12 = -0.5 * (S[5] + S[7]);
  const V c00 = h11 * h22 - h12 * h12;
  const V c01 = h02 * h12 - h01 * h22;
  const V c02 = h01 * h12 - h02 * h11;
  const V c11 = h00 * h22 - h02 * h02;
  const V c12 = h01 * h02 - h00 * h12;
  const V c22 = h00 * h11 - h01 * h01;
  const V det = h00 * c00 + h01 * c01 + h02 * c02;
  const auto newton =
      (h00 > 0) & (c22 > 0) & (det > 0) & (h00 > 1e-3) & (h11 > 1e-3) & (h22 > 1e-3);
  const V inverseDet = 1 / det;
  const V gradientScale = 1 / (absLanes(trace) + 1e-9);
  step[0] = newton ? (c00 * s0 + c01 * s1 + c02 * s2) * inverseDet : s0 * gradientScale;
  step[1] = newton ? (c01 * s0 + c11 * s1 + c12 * s2) * inverseDet : s1 * gradientScale;
  step[2] = newton ? (c02 * s0 + c12 * s1 + c22 * s2) * inverseDet : s2 * gradientScale;
  return newton;
}

// q exp(w / 2) to second order, renormalized: for small steps (angle below
// 1e-2) the error is of the order of angle^3, below the next Newton step's
// reach.
template <typename V>
TETSKIN_LANES_INLINE Quaternion<V> smallRotationStep(const Quaternion<V>& q, const V step[3]) {
  const V hx = 0.5 * step[0], hy = 0.5 * step[1], hz = 0.5 * step[2];
  Quaternion<V> r;
  r.w = q.w - (q.x * hx + q.y * hy + q.z * hz);
  r.x = q.w * hx + q.x + (q.y * hz - q.z * hy);
  r.y = q.w * hy + q.y + (q.z * hx - q.x * hz);
  r.z = q.w * hz + q.z + (q.x * hy - q.y * hx);
  const V inverseNorm = 1 / sqrtLanes(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  r.w *= inverseNorm;
  r.x *= inverseNorm;
  r.y *= inverseNorm;
  r.z *= inverseNorm;
  return r;
}

// The angles that end the iteration: below kConverged the current R is the
// answer; after a Newton step below kFinalStep the error is of the order of
// its square (1e-12), so no confirming step; steps of kSmallStep and more
// take the exact exponential (scalar code only).
inline constexpr double kConverged = 1e-14;
inline constexpr double kFinalStep = 1e-6;
inline constexpr double kSmallStep = 1e-2;

// The Newton iteration's common case, in every lane at once: from q (unit,
// updated in place), up to `iterations` small Newton steps on A = F / |F|.
// Lanes that converge get R and are set in the result; lanes that need
// anything else (a gradient step, a large step, a degenerate F, more
// iterations) are left for the scalar iteration, which takes them from the
// q left here.
template <typename V>
TETSKIN_LANES_INLINE MaskOf<V> polarRotationSmallSteps(const V F[9], Quaternion<V>& q, V R[9],
                                                       int iterations) {
  V squaredNorm = F[0] * F[0];
  for (int k = 1; k < 9; ++k) squaredNorm += F[k] * F[k];
  const V scale = sqrtLanes(squaredNorm);
  auto failed = !((scale > 0) & (scale < 1e300));  // also NaN
  const V inverseScale = 1 / (failed ? V{} + 1 : scale);
  V A[9];
  for (int k = 0; k < 9; ++k) A[k] = F[k] * inverseScale;
  auto done = noLanes<V>();
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const auto active = !(done | failed);
    if (!any(active)) break;
    V Rq[9], step[3];
    const auto newton = rotationStep(q, A, Rq, step);
    const V angle = sqrtLanes(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
    const auto converged = active & (angle < kConverged);
    const auto stepping = active & !converged & newton & (angle < kSmallStep);
    failed = failed | (active & !converged & !stepping);
    const Quaternion<V> next = smallRotationStep(q, step);
    q.w = stepping ? next.w : q.w;
    q.x = stepping ? next.x : q.x;
    q.y = stepping ? next.y : q.y;
    q.z = stepping ? next.z : q.z;
    const auto finalStep = stepping & (angle < kFinalStep);
    if (any(finalStep)) {
      V Rnext[9];
      rotationMatrix(q, Rnext);
      for (int k = 0; k < 9; ++k) Rq[k] = finalStep ? Rnext[k] : Rq[k];
    }
    const auto finished = converged | finalStep;
    for (int k = 0; k < 9; ++k) R[k] = finished ? Rq[k] : R[k];
    done = done | finished;
  }
  return done;
}

}  // namespace tetskin::lanes

#pragma GCC diagnostic pop
