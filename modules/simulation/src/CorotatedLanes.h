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

// One Jacobi rotation of the symmetric 3x3 matrix a (row-major, kept
// symmetric) in the plane (p, q), chosen to zero a_pq, and the same rotation
// applied to the columns p and q of Q (Numerical Recipes' formulas; a lane
// whose a_pq is already zero is left alone).
template <typename V>
TETSKIN_LANES_INLINE void jacobiRotation(V a[9], V Q[9], int p, int q) {
  const int r = 3 - p - q;
  const V apq = a[3 * p + q];
  const auto zero = apq == 0;
  const V theta = (a[3 * q + q] - a[3 * p + p]) / (2 * (zero ? V{} + 1 : apq));
  // (theta^2 overflows to infinity for a negligible a_pq: then t = 0.)
  const V magnitude = 1 / (absLanes(theta) + sqrtLanes(theta * theta + 1));
  const V t = zero ? V{} : (theta < 0 ? -magnitude : magnitude);
  const V c = 1 / sqrtLanes(t * t + 1), s = t * c;
  a[3 * p + p] -= t * apq;
  a[3 * q + q] += t * apq;
  a[3 * p + q] = a[3 * q + p] = V{};
  const V arp = a[3 * r + p], arq = a[3 * r + q];
  a[3 * r + p] = a[3 * p + r] = c * arp - s * arq;
  a[3 * r + q] = a[3 * q + r] = s * arp + c * arq;
  for (int k = 0; k < 3; ++k) {
    const V qp = Q[3 * k + p], qq = Q[3 * k + q];
    Q[3 * k + p] = c * qp - s * qq;
    Q[3 * k + q] = s * qp + c * qq;
  }
}

// Eigen-decomposition of a symmetric 3x3 matrix by `sweeps` cyclic sweeps of
// Jacobi rotations: a ends (nearly) diagonal, its diagonal the eigenvalues,
// and Q (orthogonal to rounding) holds the eigenvectors as columns, so that
// a_in = Q a_out Q^T. The off-diagonal part shrinks quadratically once the
// angles are small. Over 1e5 random symmetric matrices the worst
// off-diagonal part left, relative to the matrix's norm, was 8e-2 after two
// sweeps, 2e-5 after three and 1e-20 after four.
template <typename V>
TETSKIN_LANES_INLINE void symmetricEigenJacobi(V a[9], V Q[9], int sweeps) {
  for (int k = 0; k < 9; ++k) Q[k] = V{} + (k % 4 == 0 ? 1.0 : 0.0);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    jacobiRotation(a, Q, 0, 1);
    jacobiRotation(a, Q, 0, 2);
    jacobiRotation(a, Q, 1, 2);
  }
}

// The sum of two principal stretches below which the rotation term takes
// this value instead (see rotationTermModes).
inline constexpr double kRotationTermMinimumStretchSum = 0.5;

// The rotation term of the corotated tangent stiffness. The force of the
// corotated element, f_k = -V R sigma(S - I) g_k with F = R S, depends on
// the positions through R as well; R K_e R^T (the stiffness warping of
// Müller et al.) leaves that out, and so misses the stiffening of rotations
// under tension that keeps a stretched body steady under large steps.
// Differentiating the polar decomposition (McAdams et al. 2011, "Efficient
// elasticity for character skinning with contact and collisions") adds
//     dx^T K_rot dx = (V / 2) w^T R H R^T w,  w = sum_k r_k x dx_k,
// r_k = R g_k, H = 2 mu I + 2 (lambda tr(E) - 2 mu) (tr(S) I - S)^-1,
// E = S - I. H shares S's eigenvectors; its eigenvalues
//     h_i = 2 ((lambda + mu) tr(E) - mu e_i) / (tr(S) - s_i)
// (e_i, s_i = 1 + e_i those of E and S) are positive under tension and
// negative under compression (the caller drops those from the matrix, see
// CorotatedElementPass.cpp). A denominator, the sum of two principal
// stretches, below kRotationTermMinimumStretchSum (an element flattened or
// inverted, where the polar decomposition's derivative grows without bound)
// is taken as that value. Out: h and the world-frame axes U = R Q
// (columns), so that R H R^T = sum_i h_i u_i u_i^T. E is the symmetric
// rotated-frame strain, R row-major.
template <typename V>
TETSKIN_LANES_INLINE void rotationTermModes(const V E[9], const V R[9], V lambda, V mu, V h[3],
                                            V U[9]) {
  // Three sweeps: over 1e5 random strains of up to 10%, the H they give
  // differed from the exact decomposition's by at most 6e-6 mu (4e-2 mu
  // after two sweeps).
  V a[9], Q[9];
  for (int k = 0; k < 9; ++k) a[k] = E[k];
  symmetricEigenJacobi(a, Q, 3);
  const V trace = E[0] + E[4] + E[8];
  for (int i = 0; i < 3; ++i) {
    const V stretchSum = 2 + trace - a[4 * i];  // tr(S) - s_i
    const V denominator = stretchSum < kRotationTermMinimumStretchSum
                              ? V{} + kRotationTermMinimumStretchSum
                              : stretchSum;
    h[i] = 2 * ((lambda + mu) * trace - mu * a[4 * i]) / denominator;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      U[3 * i + j] = R[3 * i] * Q[j] + R[3 * i + 1] * Q[3 + j] + R[3 * i + 2] * Q[6 + j];
}

}  // namespace tetskin::lanes

#pragma GCC diagnostic pop
