// SPDX-License-Identifier: AGPL-3.0-or-later
#include "CorotatedElementPass.h"

#include <algorithm>

#include "CorotatedLanes.h"
#include "SimdTarget.h"

// Four-double vectors passed by value change the ABI between AVX and
// baseline code, which GCC warns of; the helpers here that take or return
// them are always inlined, so no call passes one.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tetskin::corotated {

using lanes::Double4;

namespace {

// Vector Newton steps per group before its remaining lanes go to the scalar
// iteration: warm-started from the last step, an element needs one step
// and, unless that step was already below kFinalStep, one or two more.
constexpr int kVectorRotationSteps = 4;

TETSKIN_LANES_INLINE Double4 load(const double* p) {
  Double4 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

// F = sum_k x_k g_k^T in each lane (row-major), x gathered by node.
TETSKIN_LANES_INLINE void deformationGradients(const ElementGroup& group, const double* x,
                                               Double4 F[9]) {
  for (int k = 0; k < 9; ++k) F[k] = Double4{};
  for (int k = 0; k < 4; ++k) {
    const int* nodes = group.nodes[k];
    for (int a = 0; a < 3; ++a) {
      const Double4 xka{x[3 * nodes[0] + a], x[3 * nodes[1] + a], x[3 * nodes[2] + a],
                        x[3 * nodes[3] + a]};
      for (int b = 0; b < 3; ++b) F[3 * a + b] += xka * load(group.gradients[k][b]);
    }
  }
}

// sym(R^T M), row-major.
TETSKIN_LANES_INLINE void symmetricRotatedFrame(const Double4 R[9], const Double4 M[9],
                                                Double4 out[9]) {
  Double4 G[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      G[3 * i + j] = R[i] * M[j] + R[3 + i] * M[3 + j] + R[6 + i] * M[6 + j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = 0.5 * (G[3 * i + j] + G[3 * j + i]);
}

// The scalar iteration for the lanes the vector steps left (rare: a large
// rotation within one step, an inverted or degenerate element). F and R
// row-major, q as w, x, y, z.
[[gnu::noinline]] void scalarRotation(const double F[9], double q[4], double R[9]) {
  Eigen::Quaterniond estimate(q[0], q[1], q[2], q[3]);
  const Eigen::Matrix3d rotation = CorotatedFem::rotation(
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(F), estimate);
  q[0] = estimate.w();
  q[1] = estimate.x();
  q[2] = estimate.y();
  q[3] = estimate.z();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[3 * i + j] = rotation(i, j);
}

// (L R^T)_ab for row-major L and R.
TETSKIN_LANES_INLINE Double4 timesTransposeEntry(const Double4 L[9], const Double4 R[9], int a,
                                                 int b) {
  return L[3 * a] * R[3 * b] + L[3 * a + 1] * R[3 * b + 1] + L[3 * a + 2] * R[3 * b + 2];
}

// The rotation term of the tangent (CorotatedLanes.h, rotationTermModes):
// K_rot = (V / 2) sum_m h_m z_m z_m^T over the modes m, with z_m the 12
// entries z_km = u_m x r_k, added to the blocks with weight q =
// args.rotationScale, and -K_rot v to the forces with weight
// args.rotationVelocityWeight.
//
// In the matrix its negative modes (compression) are dropped, as Teran et
// al. (2005) project the element Hessian: K_rot stays positive
// semidefinite and the system positive definite however large the step.
// (Bounding them element by element by the lumped mass instead does not
// do: at 1/60 s steps the mass is far below h^2 times their size, and only
// the neighbours' stiffness, which one element cannot see, keeps the
// system definite.)
//
// The force keeps every mode: -h K_rot v is part of the force's
// linearization at the predicted positions, f(x + h v) = f(x) - h K_T v,
// the step's right-hand side, which the matrix, an approximation of the
// Jacobian that only has to be definite, does not constrain. With the
// modes dropped there as well the bunny's 12.7k wobble took 52.6 CG
// iterations per step against 41.9 (39.5 with R K R^T alone): switching
// the velocity term on and off as elements pass between tension and
// compression spoils the initial guess from the last solutions.
TETSKIN_LANES_INLINE void addRotationTerm(const PassArgs& args, const Double4 E[9],
                                          const Double4* velocityGradient, const Double4 R[9],
                                          const Double4 r[4][3], Double4 volume, Double4 lambda,
                                          Double4 mu, Double4 f[4][3], Double4 blocks[10][9]) {
  Double4 h[3], U[9];
  lanes::rotationTermModes(E, R, lambda, mu, h, U);
  Double4 z[4][3][3];  // [node][mode][axis]
  for (int m = 0; m < 3; ++m) {
    const Double4 u0 = U[m], u1 = U[3 + m], u2 = U[6 + m];
    for (int k = 0; k < 4; ++k) {
      z[k][m][0] = u1 * r[k][2] - u2 * r[k][1];
      z[k][m][1] = u2 * r[k][0] - u0 * r[k][2];
      z[k][m][2] = u0 * r[k][1] - u1 * r[k][0];
    }
  }
  const Double4 halfVolume = 0.5 * volume;
  Double4 weight[3];  // of each mode in the matrix: compressive ones dropped
  for (int m = 0; m < 3; ++m)
    weight[m] = args.rotationScale * halfVolume * (h[m] < 0 ? Double4{} : h[m]);
  for (int i = 0, pair = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j, ++pair)
      for (int a = 0; a < 3; ++a) {
        const Double4 w0 = weight[0] * z[i][0][a], w1 = weight[1] * z[i][1][a],
                      w2 = weight[2] * z[i][2][a];
        for (int b = 0; b < 3; ++b)
          blocks[pair][3 * a + b] += w0 * z[j][0][b] + w1 * z[j][1][b] + w2 * z[j][2][b];
      }
  if (!velocityGradient || args.rotationVelocityWeight == 0) return;
  // z_m . v = sum_k (u_m x r_k) . v_k = u_m . w with w = sum_k r_k x v_k, the
  // axial vector of A - A^T for A = sum_k v_k r_k^T = L R^T, L the velocity
  // gradient the pass already has.
  const Double4* L = velocityGradient;
  const Double4 w0 = timesTransposeEntry(L, R, 2, 1) - timesTransposeEntry(L, R, 1, 2),
                w1 = timesTransposeEntry(L, R, 0, 2) - timesTransposeEntry(L, R, 2, 0),
                w2 = timesTransposeEntry(L, R, 1, 0) - timesTransposeEntry(L, R, 0, 1);
  Double4 modeVelocity[3];  // z_m . v, then weighted
  for (int m = 0; m < 3; ++m) modeVelocity[m] = U[m] * w0 + U[3 + m] * w1 + U[6 + m] * w2;
  for (int m = 0; m < 3; ++m) modeVelocity[m] *= args.rotationVelocityWeight * halfVolume * h[m];
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a)
      f[k][a] -= modeVelocity[0] * z[k][0][a] + modeVelocity[1] * z[k][1][a] +
                 modeVelocity[2] * z[k][2][a];
}

// Three lane vectors (entries 0, 1, 2 of a matrix row, one element per
// lane) turned into one vector per element holding its three entries (the
// fourth zero): a 4x4 transpose with a zero row.
TETSKIN_LANES_INLINE void transposeRows(Double4 r0, Double4 r1, Double4 r2, Double4 out[4]) {
  using Index4 = long long __attribute__((vector_size(32)));
  const Double4 r3{};
  const Double4 t0 = __builtin_shuffle(r0, r1, Index4{0, 4, 2, 6});
  const Double4 t1 = __builtin_shuffle(r0, r1, Index4{1, 5, 3, 7});
  const Double4 t2 = __builtin_shuffle(r2, r3, Index4{0, 4, 2, 6});
  const Double4 t3 = __builtin_shuffle(r2, r3, Index4{1, 5, 3, 7});
  out[0] = __builtin_shuffle(t0, t2, Index4{0, 1, 4, 5});
  out[1] = __builtin_shuffle(t1, t3, Index4{0, 1, 4, 5});
  out[2] = __builtin_shuffle(t0, t2, Index4{2, 3, 6, 7});
  out[3] = __builtin_shuffle(t1, t3, Index4{2, 3, 6, 7});
}

// Adds the first three lanes of `row` to target[0..2]: two lanes as one
// vector, the third alone (the entry after them may be another thread's).
// Against three scalar additions per row, from lanes read one at a time,
// the element pass took about 0.9 of the time at 12.7k and 109k elements
// with the AVX2 kernel (the same with the baseline one; simulation_bench's
// element pass line, the two builds alternating). Adding the forces the
// same way gained nothing with AVX2 and cost 1.5x with the baseline.
TETSKIN_LANES_INLINE void addRow(double* target, Double4 row) {
  using Double2 = double __attribute__((vector_size(16)));
  Double2 pair;
  __builtin_memcpy(&pair, target, sizeof pair);
  pair += Double2{row[0], row[1]};
  __builtin_memcpy(target, &pair, sizeof pair);
  target[2] += row[2];
}

// Adds row `row` of block (i, j) of each of the group's `elements`
// (`scatter` says where), its three entries given one lane per element.
// Always inlined, as every function here that takes four-double vectors:
// a lambda would be one function for both kernels (at -O0 a call), which
// the AVX2 kernel passes the vectors in registers and the baseline code
// reads from the stack (Debug builds assembled garbage so).
TETSKIN_LANES_INLINE void addBlockRow(double* values, const ElementScatter* scatter, int elements,
                                      int i, int j, int row, Double4 e0, Double4 e1, Double4 e2) {
  Double4 rows[4];
  transposeRows(e0, e1, e2, rows);
  for (int l = 0; l < elements; ++l)
    addRow(values + scatter[l].slots[i * 4 + j] + row * scatter[l].rowLengths[i], rows[l]);
}

// One group of four elements: rotations (warm-started), forces
// f_k = -V R sigma g_k and the ten blocks (i, j >= i) of R K_e R^T, each
// V (lambda r_i r_j^T + mu r_j r_i^T + mu (g_i . g_j) I) with r_k = R g_k;
// sigma is the stress of the rotated-frame strain plus w times the
// rotated-frame velocity gradient's (K_e applied to R^T v_e, by linearity).
// Then the results are added in: forces element by element, each block row
// (three entries, one lane per element) turned into one vector per element
// first (transposeRows).
TETSKIN_LANES_INLINE void assembleGroup(const PassArgs& args, std::size_t g) {
  const ElementGroup& group = args.groups[g];
  RotationEstimates& estimate = args.estimates[g];
  const int elements = static_cast<int>(std::min<std::size_t>(4, args.elementCount - 4 * g));
  Double4 F[9];
  deformationGradients(group, args.x, F);
  lanes::Quaternion<Double4> q{load(estimate.w), load(estimate.x), load(estimate.y),
                               load(estimate.z)};
  Double4 R[9] = {};
  const lanes::Mask4 done = lanes::polarRotationSmallSteps(F, q, R, kVectorRotationSteps);
  for (int l = 0; l < elements; ++l) {
    if (done[l]) continue;
    double lane[9], quaternion[4] = {q.w[l], q.x[l], q.y[l], q.z[l]}, rotation[9];
    for (int k = 0; k < 9; ++k) lane[k] = F[k][l];
    scalarRotation(lane, quaternion, rotation);
    q.w[l] = quaternion[0];
    q.x[l] = quaternion[1];
    q.y[l] = quaternion[2];
    q.z[l] = quaternion[3];
    for (int k = 0; k < 9; ++k) R[k][l] = rotation[k];
  }
  __builtin_memcpy(estimate.w, &q.w, sizeof q.w);
  __builtin_memcpy(estimate.x, &q.x, sizeof q.x);
  __builtin_memcpy(estimate.y, &q.y, sizeof q.y);
  __builtin_memcpy(estimate.z, &q.z, sizeof q.z);

  Double4 strain[9];
  symmetricRotatedFrame(R, F, strain);
  strain[0] -= 1;
  strain[4] -= 1;
  strain[8] -= 1;
  Double4 elasticStrain[9];  // before the velocity's share: the rotation term's E
  for (int k = 0; k < 9; ++k) elasticStrain[k] = strain[k];
  Double4 velocityGradient[9];
  if (args.velocity) {
    Double4 rate[9];
    deformationGradients(group, args.velocity, velocityGradient);
    symmetricRotatedFrame(R, velocityGradient, rate);
    for (int k = 0; k < 9; ++k) strain[k] += args.velocityWeight * rate[k];
  }
  const Double4 volume = load(group.volume);
  const Double4 lameLambda = load(group.lambda), lameMu = load(group.mu);
  const Double4 lambdaTrace = lameLambda * (strain[0] + strain[4] + strain[8]);
  Double4 sigma[9];
  for (int k = 0; k < 9; ++k) sigma[k] = (2 * lameMu) * strain[k];
  sigma[0] += lambdaTrace;
  sigma[4] += lambdaTrace;
  sigma[8] += lambdaTrace;
  Double4 P[9];  // V R sigma
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      P[3 * i + j] = volume * (R[3 * i] * sigma[j] + R[3 * i + 1] * sigma[3 + j] +
                               R[3 * i + 2] * sigma[6 + j]);
  Double4 f[4][3], r[4][3];
  for (int k = 0; k < 4; ++k) {
    const Double4 g0 = load(group.gradients[k][0]), g1 = load(group.gradients[k][1]),
                  g2 = load(group.gradients[k][2]);
    for (int a = 0; a < 3; ++a) {
      f[k][a] = -(P[3 * a] * g0 + P[3 * a + 1] * g1 + P[3 * a + 2] * g2);
      r[k][a] = R[3 * a] * g0 + R[3 * a + 1] * g1 + R[3 * a + 2] * g2;
    }
  }
  Double4 blocks[10][9];
  const Double4 mu = args.stiffnessScale * lameMu;
  const Double4 volumeLambda = volume * (args.stiffnessScale * lameLambda), volumeMu = volume * mu;
  for (int i = 0, pair = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j, ++pair) {
      const Double4 isotropic = mu * load(group.gradientDots[pair]);
      for (int a = 0; a < 3; ++a) {
        const Double4 li = volumeLambda * r[i][a], mj = volumeMu * r[j][a];
        for (int b = 0; b < 3; ++b)
          blocks[pair][3 * a + b] = li * r[j][b] + mj * r[i][b] + (a == b ? isotropic : Double4{});
      }
    }
  if (args.rotationScale != 0 || args.rotationVelocityWeight != 0)
    addRotationTerm(args, elasticStrain, args.velocity ? velocityGradient : nullptr, R, r, volume,
                    lameLambda, lameMu, f, blocks);

  for (int l = 0; l < elements; ++l) {
    const std::size_t e = 4 * g + static_cast<std::size_t>(l);
    double* rotation = args.rotations + 9 * e;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rotation[3 * j + i] = R[3 * i + j][l];
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) args.force[3 * group.nodes[k][l] + a] += f[k][a][l];
  }
  const ElementScatter* scatter = args.scatter + 4 * g;
  for (int i = 0, pair = 0; i < 4; ++i)
    for (int j = i; j < 4; ++j, ++pair) {
      const Double4* B = blocks[pair];
      for (int a = 0; a < 3; ++a)
        addBlockRow(args.values, scatter, elements, i, j, a, B[3 * a], B[3 * a + 1], B[3 * a + 2]);
      if (j == i) continue;
      // Block (j, i) is the transpose: its row b is column b of (i, j).
      for (int b = 0; b < 3; ++b)
        addBlockRow(args.values, scatter, elements, j, i, b, B[b], B[3 + b], B[6 + b]);
    }
}

// Baseline (SSE2: each four-lane operation is two instructions).
void assembleGroupsBaseline(const PassArgs& args, std::size_t first, std::size_t last) {
  for (std::size_t g = first; g < last; ++g) assembleGroup(args, g);
}

TETSKIN_AVX2_TARGET void assembleGroupsAvx2(const PassArgs& args, std::size_t first,
                                            std::size_t last) {
  for (std::size_t g = first; g < last; ++g) assembleGroup(args, g);
}

}  // namespace

GroupsKernel groupsKernel(SimdKernel kernel) {
  return chooseKernel<GroupsKernel>(kernel, assembleGroupsAvx2, assembleGroupsBaseline);
}

}  // namespace tetskin::corotated
