// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/LinearSolvers.h"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include "GalerkinStream.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {

// The node-block layout (CorotatedFem::pattern()): rows 3v, 3v+1, 3v+2 share
// one sorted column list made of whole triples 3c, 3c+1, 3c+2. The kernels
// below read one column index per 3x3 block instead of one per entry.
bool hasNodeBlocks(const SparseMatrix& A) {
  if (!hasNodeRowLengths(A)) return false;
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  for (Index v = 0; v < A.rows() / 3; ++v) {
    const int start = outer[3 * v], length = outer[3 * v + 1] - start;
    for (int k = 0; k < length; ++k) {
      const int column = inner[start + k];
      if (column != inner[start + k - k % 3] + k % 3 || column % 3 != k % 3) return false;
      for (int a = 1; a < 3; ++a)
        if (inner[outer[3 * v + a] + k] != column) return false;
    }
  }
  return true;
}

namespace {

// y = A x over A's node-block pattern.
void multiplyBlocks(const SparseMatrix& A, const double* in, double* out) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* values = A.valuePtr();
  parallelFor<int>(0, static_cast<int>(A.rows() / 3), 256, [&](const auto& r) {
    for (int v = r.begin(); v != r.end(); ++v) {
      const int start = outer[3 * v], length = outer[3 * v + 1] - start;
      const int* columns = inner + start;
      const double* row0 = values + start;
      const double* row1 = values + outer[3 * v + 1];
      const double* row2 = values + outer[3 * v + 2];
      double s0 = 0, s1 = 0, s2 = 0;
      for (int k = 0; k < length; k += 3) {
        const double* xc = in + columns[k];
        s0 += row0[k] * xc[0] + row0[k + 1] * xc[1] + row0[k + 2] * xc[2];
        s1 += row1[k] * xc[0] + row1[k + 1] * xc[1] + row1[k + 2] * xc[2];
        s2 += row2[k] * xc[0] + row2[k + 1] * xc[1] + row2[k + 2] * xc[2];
      }
      out[3 * v] = s0;
      out[3 * v + 1] = s1;
      out[3 * v + 2] = s2;
    }
  });
}

// y = P x for a nodal P on xyz vectors of Scalar.
template <typename Scalar>
void multiplyNodalBlocks(const SparseMatrix& P, const Scalar* in, Scalar* out) {
  const int* outer = P.outerIndexPtr();
  const int* inner = P.innerIndexPtr();
  const double* values = P.valuePtr();
  parallelFor<int>(0, static_cast<int>(P.rows()), 512, [&](const auto& r) {
    for (int i = r.begin(); i != r.end(); ++i) {
      Scalar s0 = 0, s1 = 0, s2 = 0;
      for (int k = outer[i]; k < outer[i + 1]; ++k) {
        const auto w = static_cast<Scalar>(values[k]);
        const Scalar* xc = in + 3 * inner[k];
        s0 += w * xc[0];
        s1 += w * xc[1];
        s2 += w * xc[2];
      }
      out[3 * i] = s0;
      out[3 * i + 1] = s1;
      out[3 * i + 2] = s2;
    }
  });
}

}  // namespace

void multiply(const SparseMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  if (y.size() != A.rows()) y.resize(A.rows());
  multiplyBlocks(A, x.data(), y.data());
}

void multiplyNodal(const SparseMatrix& P, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  if (y.size() != 3 * P.rows()) y.resize(3 * P.rows());
  multiplyNodalBlocks(P, x.data(), y.data());
}

namespace {

// (Node-block layout: the block's first column found by binary search in
// the node's first row; the other rows hold it at the same offset.)
Eigen::Matrix3d diagonalBlock(const SparseMatrix& A, Index node) {
  Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
  const int* outer = A.outerIndexPtr();
  const int* begin = A.innerIndexPtr() + outer[3 * node];
  const int* end = A.innerIndexPtr() + outer[3 * node + 1];
  const int* found = std::lower_bound(begin, end, static_cast<int>(3 * node));
  if (found == end || *found != 3 * node) return block;
  const auto offset = found - begin;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) block(a, b) = A.valuePtr()[outer[3 * node + a] + offset + b];
  return block;
}

// The order of a Gauss-Seidel sweep: the matrix's own node order, cut into
// chunks of consecutive nodes, and the chunks coloured so that no two chunks
// of one colour are coupled in A. A sweep relaxes the colours one after
// another, the chunks of a colour in parallel and the nodes of a chunk in
// order: deterministic, and each chunk reads a few consecutive rows. The
// caller numbers the nodes for locality (Simulation numbers every level
// breadth first, NodeOrder.h): a sweep in memory order runs about twice as
// fast as one in a breadth-first order of its own over scattered rows
// (measured on the 109k-element bunny: 2.1 against 4.5 ms).
struct SweepOrder {
  std::vector<std::vector<int>> colours;  // per colour: the first nodes of its chunks
  // Per node, its place in a forward sweep (colour by colour, the chunks of
  // a colour in list order): coupled nodes are relaxed in rank order, since
  // two chunks of one colour share no coupling.
  std::vector<int> rank;
};

constexpr int kSweepChunk = 32;

SweepOrder sweepOrder(const SparseMatrix& A) {
  const int count = static_cast<int>(A.rows() / 3);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  auto forNeighbours = [&](int v, auto&& visit) {  // one column index per block
    for (int k = outer[3 * v]; k < outer[3 * v + 1]; k += 3) visit(inner[k] / 3);
  };
  SweepOrder order;
  // A chunk may join a colour if none of its nodes is in or next to a chunk
  // of that colour already.
  std::vector<std::vector<char>> covered;  // per colour, per node
  for (int first = 0; first < count; first += kSweepChunk) {
    const int last = std::min(count, first + kSweepChunk);
    std::size_t c = 0;
    for (;; ++c) {
      if (c == covered.size()) {
        covered.emplace_back(static_cast<std::size_t>(count), 0);
        order.colours.emplace_back();
      }
      bool free = true;
      for (int v = first; free && v < last; ++v) free = !covered[c][static_cast<std::size_t>(v)];
      if (free) break;
    }
    order.colours[c].push_back(first);
    for (int v = first; v < last; ++v)
      forNeighbours(v, [&](int u) { covered[c][static_cast<std::size_t>(u)] = 1; });
  }
  order.rank.resize(static_cast<std::size_t>(count));
  int next = 0;
  for (const std::vector<int>& chunks : order.colours)
    for (int first : chunks)
      for (int v = first; v < std::min(count, first + kSweepChunk); ++v)
        order.rank[static_cast<std::size_t>(v)] = next++;
  return order;
}

// Asks for node u's row of blocks to be brought into the cache. Always
// inlined: as a function of its own, GCC finds it free of side effects
// and drops the call.
template <typename Scalar>
[[gnu::always_inline]] inline void prefetchBlockRow(const BasicNodeBlockMatrix<Scalar>& A, int u) {
  const auto row = [&](int node) {
    return reinterpret_cast<const char*>(A.values().data() +
                                         BasicNodeBlockMatrix<Scalar>::kBlockEntries *
                                             static_cast<std::ptrdiff_t>(A.blockStarts()[node]));
  };
  for (const char *line = row(u), *end = row(u + 1); line < end; line += 64)
    __builtin_prefetch(line);
  __builtin_prefetch(A.columns().data() + A.blockStarts()[u]);
}

// How many nodes ahead a backward sweep prefetches rows: the hardware
// prefetcher follows the ascending reads of a forward sweep but not rows
// taken in descending order, and without help the backward sweep took
// about 2.5x as long as the forward one at 109k elements (float blocks,
// e.g. 3.1 against 1.2 ms per sweep on 2 threads, 6.0 against 2.2 on one).
constexpr int kBackwardPrefetchNodes = 3;

// Calls relax(v) for every node in the sweep order, or exactly backwards
// (colours, and nodes within each chunk) where `forward` is false; the
// chunks of a colour on both threads where the level is large enough.
template <typename Relax>
void sweepNodes(const SweepOrder& order, int count, bool forward, Relax&& relax) {
  auto sweepChunk = [&](int first) {
    const int last = std::min(count, first + kSweepChunk);
    if (forward)
      for (int v = first; v < last; ++v) relax(v);
    else
      for (int v = last; v-- > first;) relax(v);
  };
  for (std::size_t i = 0; i < order.colours.size(); ++i) {
    const std::vector<int>& chunks = order.colours[forward ? i : order.colours.size() - 1 - i];
    if (count < 2048) {  // too little work to share between threads
      for (int first : chunks) sweepChunk(first);
      continue;
    }
    parallelFor<std::size_t>(0, chunks.size(), 2, [&](const auto& range) {
      for (std::size_t c = range.begin(); c != range.end(); ++c) sweepChunk(chunks[c]);
    });
  }
}

// x_v = D_v^-1 (b_v - sums) for node v's 3 unknowns.
template <typename Scalar>
[[gnu::always_inline]] inline void solveNode(
    const std::vector<Eigen::Matrix<Scalar, 3, 3>>& inverseDiagonal, int v, const Scalar* b,
    const Scalar sums[3], Scalar* x) {
  Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>(x + 3 * v) =
      inverseDiagonal[static_cast<std::size_t>(v)] *
      Eigen::Matrix<Scalar, 3, 1>(b[3 * v] - sums[0], b[3 * v + 1] - sums[1],
                                  b[3 * v + 2] - sums[2]);
}

// One block Gauss-Seidel sweep: each node's 3 unknowns solved together
// (x_v = D_v^-1 (b_v - sum_{u != v} A_vu x_u)) in the sweep order; `forward`
// false runs it exactly backwards, so a forward and a backward sweep make a
// symmetric smoother.
template <typename Scalar>
void blockGaussSeidel(const BasicNodeBlockMatrix<Scalar>& A,
                      const std::vector<Eigen::Matrix<Scalar, 3, 3>>& inverseDiagonal,
                      const SweepOrder& order, const Scalar* b, Scalar* x, bool forward) {
  sweepNodes(order, static_cast<int>(A.nodeCount()), forward, [&](int v) {
    if (!forward && v >= kBackwardPrefetchNodes) prefetchBlockRow(A, v - kBackwardPrefetchNodes);
    Scalar sums[3];  // sum_{u != v} A_vu x_u
    blockRowSum(A, v, x, 3 * v, sums);
    solveNode(inverseDiagonal, v, b, sums, x);
  });
}

// The first forward sweep from x = 0 on a copy in sweep order
// (assignInSweepOrder): the nodes not yet relaxed hold zero, so each node
// reads only its earlier neighbours' blocks, and x need not be cleared
// first. The residual b - A x after it is, node by node, minus the sum
// over the later neighbours' blocks (b_v - D_v x_v - the earlier ones is
// zero up to rounding by the sweep's own equation): the two read each block
// once between them, where a sweep and a product read every block twice.
template <typename Scalar>
void forwardSweepFromZero(const BasicNodeBlockMatrix<Scalar>& A,
                          const std::vector<Eigen::Matrix<Scalar, 3, 3>>& inverseDiagonal,
                          const SweepOrder& order, const Scalar* b, Scalar* x) {
  sweepNodes(order, static_cast<int>(A.nodeCount()), true, [&](int v) {
    Scalar sums[3];
    blockRangeSum(A, A.blockStarts()[static_cast<std::size_t>(v)], A.laterBlocks(v), x, 3 * v,
                  sums);
    solveNode(inverseDiagonal, v, b, sums, x);
  });
}

template <typename Scalar>
void residualAfterSweepFromZero(const BasicNodeBlockMatrix<Scalar>& A, const Scalar* x, Scalar* r) {
  parallelFor<Index>(0, A.nodeCount(), 256, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      Scalar sums[3];
      blockRangeSum(A, A.laterBlocks(v), A.blockStarts()[static_cast<std::size_t>(v) + 1], x, -1,
                    sums);
      for (int a = 0; a < 3; ++a) r[3 * v + a] = -sums[a];
    }
  });
}

template <typename Scalar>
Eigen::Matrix3d diagonalBlock(const BasicNodeBlockMatrix<Scalar>& A, Index node) {
  return A.diagonalBlock(node).template cast<double>();
}

// Inverse 3x3 diagonal blocks (identity where a block is singular) of a
// SparseMatrix or a block copy. (Inverted in double, stored in Scalar.)
// Singular is judged against the block's own size: the entries are node
// masses (kg) plus h and h^2 times stiffnesses, and Eigen's default test,
// |det| > 1e-12, called singular the blocks of nodes lighter than about
// 1e-4 kg: the bunny scaled to 5 cm with the density of water has a block
// of norm 1.7e-5 (determinant 6e-16) among others, and the identity in
// their place made CG take 960 iterations per step where the blocks'
// inverses take 42 (doc/user/simulation.md: Solvers).
template <typename Matrix, typename Scalar>
void invertDiagonalBlocks(const Matrix& A, std::vector<Eigen::Matrix<Scalar, 3, 3>>& inverse) {
  const Index nodes = A.rows() / 3;
  inverse.resize(static_cast<std::size_t>(nodes));
  parallelFor<Index>(0, nodes, 256, [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Matrix3d block = diagonalBlock(A, v);
      const double size = block.norm();
      Eigen::Matrix3d result;
      double determinant = 0;
      bool invertible = false;
      block.computeInverseAndDetWithCheck(result, determinant, invertible,
                                          1e-12 * size * size * size);
      inverse[static_cast<std::size_t>(v)] =
          (invertible ? result : Eigen::Matrix3d::Identity()).cast<Scalar>();
    }
  });
}

// The per-level data of a V-cycle in Scalar: the level matrices copied into
// 3x3 blocks (NodeBlockMatrix.h; in float by default, which also
// halves the memory traffic of the sweeps and products that bound the
// cycle) and their inverse diagonal blocks.
template <typename Scalar>
struct Cycle {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  std::vector<BasicNodeBlockMatrix<Scalar>> blocks;                        // per level
  std::vector<std::vector<Eigen::Matrix<Scalar, 3, 3>>> inverseDiagonals;  // per level
  std::vector<Vector> b, x, r;  // scratch per level: right-hand side, solution, residual
  // Chebyshev smoothing: per level the search direction and its successor,
  // and the largest eigenvalue of D^-1 A with its eigenvector estimate.
  std::vector<Vector> d, nextD, eigenvector;
  std::vector<double> largestEigenvalue;

  void resize(std::size_t levels) {
    blocks.resize(levels);
    inverseDiagonals.resize(levels);
    b.resize(levels);
    x.resize(levels);
    r.resize(levels);
    d.resize(levels);
    nextD.resize(levels);
    eigenvector.resize(levels);
    largestEigenvalue.assign(levels, 0.0);
  }
  // After level l's matrix changed. (The diagonal blocks are read from
  // the copy: on the 109k-element level 1.7-1.8 ms against 2.6-3.5 ms from
  // A's rows. In float the inverse is that of the rounded blocks, the ones
  // the sweeps use.)
  // (Chebyshev smoothing reads whole rows in any order: the plain copy, a
  // third faster than the one in sweep order.)
  void prepare(const SparseMatrix& A, std::size_t l, const SweepOrder& order, bool inSweepOrder) {
    if (inSweepOrder)
      blocks[l].assignInSweepOrder(A, order.rank);
    else
      blocks[l].assign(A);
    invertDiagonalBlocks(blocks[l], inverseDiagonals[l]);
  }
};

// D_v^-1 r_v for node v.
template <typename Scalar>
[[gnu::always_inline]] inline Eigen::Matrix<Scalar, 3, 1> inverseDiagonalTimes(
    const std::vector<Eigen::Matrix<Scalar, 3, 3>>& inverseDiagonal, Index v, const Scalar* r) {
  return inverseDiagonal[static_cast<std::size_t>(v)] *
         Eigen::Map<const Eigen::Matrix<Scalar, 3, 1>>(r + 3 * v);
}

// The largest eigenvalue of D^-1 A on level l, by power steps from the last
// estimate's eigenvector (ones the first time): the Chebyshev smoother's
// interval. D^-1 A is similar to the symmetric D^-1/2 A D^-1/2, so its
// eigenvalues are real and positive, and the norm ratio converges to the
// largest from below (the smoother's interval reaches 1.1 times it).
// Power steps: 10 from ones, 2 from the last eigenvector, on every new
// matrix of the level (the finest each step). Estimated only with the
// coarse rebuilds, every 4th step, the eigenvalue was stale enough to cost
// iterations: at 109k 9.6 and 17.1 per step (E 2e5, 2e7) against 7.8 and
// 14.4 with 2 steps every step, whose cost did not show in the setup.
constexpr int kColdPowerSteps = 10, kWarmPowerSteps = 2;

template <typename Scalar>
void estimateLargestEigenvalue(Cycle<Scalar>& s, std::size_t l) {
  using Vector = typename Cycle<Scalar>::Vector;
  const Index rows = s.blocks[l].rows();
  Vector& v = s.eigenvector[l];
  int powerSteps = kWarmPowerSteps;
  if (v.size() != rows || !v.allFinite() || v.norm() == 0) {
    v = Vector::Ones(rows);
    powerSteps = kColdPowerSteps;
  }
  Vector& product = s.nextD[l];
  double lambda = 0;
  for (int step = 0; step < powerSteps; ++step) {
    multiply(s.blocks[l], v, product);
    parallelFor<Index>(0, rows / 3, 512, [&](const auto& range) {
      for (Index u = range.begin(); u != range.end(); ++u)
        v.template segment<3>(3 * u) =
            inverseDiagonalTimes(s.inverseDiagonals[l], u, product.data());
    });
    const double norm = v.template cast<double>().norm();
    if (!(norm > 0) || !std::isfinite(norm)) break;
    lambda = norm / std::sqrt(static_cast<double>(rows));
    v /= static_cast<Scalar>(lambda);  // (norm sqrt(rows): entries about 1)
  }
  s.largestEigenvalue[l] = lambda;
}

// The Chebyshev smoother's recurrence (Saad, Iterative Methods, alg. 12.1,
// preconditioned by D): over [a, b] = [0.15, 1.1] lambda_max, theta = (a + b) / 2,
// delta = (b - a) / 2, sigma = theta / delta; the first direction is
// D^-1 r / theta, then with rho_0 = 1 / sigma and rho_k = 1 / (2 sigma -
// rho_{k-1}), d_k = rho_k rho_{k-1} d_{k-1} + (2 rho_k / delta) D^-1 r_k.
// The interval's bottom: 0.15 took 10 / 12 / 13 iterations at 109k (E 2e5,
// 2e6, 2e7, a system at rest), 0.25 took 10 / 13 / 14 and 0.35 11 / - / 15;
// block Gauss-Seidel 11 / 14 / 15.
struct ChebyshevInterval {
  double theta = 1, delta = 1, sigma = 1;
  explicit ChebyshevInterval(double largestEigenvalue) {
    const double top = 1.1 * largestEigenvalue, bottom = 0.15 * largestEigenvalue;
    theta = 0.5 * (top + bottom);
    delta = 0.5 * (top - bottom);
    sigma = theta / delta;
  }
};

// One Chebyshev degree on level l, one pass over the nodes: r -= A d, then
// d' = previousWeight d + residualWeight D^-1 r and x += d' (d' into
// nextD, then swapped with d: the products read d of every neighbour).
// Each node's values from its own and its neighbours' old ones alone: no
// order between nodes.
template <typename Scalar>
void chebyshevDegree(Cycle<Scalar>& s, std::size_t l, double previousWeight,
                     double residualWeight) {
  const auto& A = s.blocks[l];
  const Scalar* d = s.d[l].data();
  Scalar *r = s.r[l].data(), *x = s.x[l].data(), *next = s.nextD[l].data();
  const auto previous = static_cast<Scalar>(previousWeight);
  const auto weight = static_cast<Scalar>(residualWeight);
  parallelFor<Index>(0, A.nodeCount(), 256, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      Scalar product[3];
      blockRowSum(A, v, d, -1, product);
      for (int a = 0; a < 3; ++a) r[3 * v + a] -= product[a];
      const Eigen::Matrix<Scalar, 3, 1> step =
          previous * Eigen::Map<const Eigen::Matrix<Scalar, 3, 1>>(d + 3 * v) +
          weight * inverseDiagonalTimes(s.inverseDiagonals[l], v, r);
      Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>(next + 3 * v) = step;
      Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>(x + 3 * v) += step;
    }
  });
  s.d[l].swap(s.nextD[l]);
}

// The degrees after the first: r and x kept current.
template <typename Scalar>
void chebyshevDegrees(Cycle<Scalar>& s, std::size_t l, const ChebyshevInterval& interval,
                      int degree) {
  double rho = 1 / interval.sigma;
  for (int k = 1; k < degree; ++k) {
    const double next = 1 / (2 * interval.sigma - rho);
    chebyshevDegree(s, l, next * rho, 2 * next / interval.delta);
    rho = next;
  }
}

// Pre-smoothing from x = 0 (b in s.b[l]): the polynomial, then the residual
// b - A x in s.r[l] (one more product, of the last direction).
template <typename Scalar>
void chebyshevFromZero(Cycle<Scalar>& s, std::size_t l, int degree) {
  const ChebyshevInterval interval(s.largestEigenvalue[l]);
  const Index rows = s.b[l].size();
  s.r[l] = s.b[l];
  s.x[l].resize(rows);
  s.d[l].resize(rows);
  s.nextD[l].resize(rows);
  const auto first = static_cast<Scalar>(1 / interval.theta);
  parallelFor<Index>(0, rows / 3, 512, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Eigen::Matrix<Scalar, 3, 1> step =
          first * inverseDiagonalTimes(s.inverseDiagonals[l], v, s.r[l].data());
      s.d[l].template segment<3>(3 * v) = step;
      s.x[l].template segment<3>(3 * v) = step;
    }
  });
  chebyshevDegrees(s, l, interval, degree);
  chebyshevDegree(s, l, 0, 0);  // r -= A d (the new direction, zero, unused)
}

// Post-smoothing after the coarse correction, the correction given in
// s.d[l] and already added to x: r (the pre-smoothing's residual) less A
// times it, then the same polynomial as before the correction.
template <typename Scalar>
void chebyshevAfterCorrection(Cycle<Scalar>& s, std::size_t l, int degree) {
  const ChebyshevInterval interval(s.largestEigenvalue[l]);
  chebyshevDegree(s, l, 0, 1 / interval.theta);
  chebyshevDegrees(s, l, interval, degree);
}

}  // namespace

void BlockJacobi::setup(const SparseMatrix& A) {
  invertDiagonalBlocks(A, inverse_);
}

void Preconditioner::applyToNodes(Index, Index, const double*, double*) const {
  throw Error("preconditioner: applied node by node, but it does not act per node");
}

void BlockJacobi::applyToNodes(Index first, Index last, const double* r, double* z) const {
  for (Index v = first; v != last; ++v)
    Eigen::Map<Eigen::Vector3d>(z + 3 * v) =
        inverse_[static_cast<std::size_t>(v)] * Eigen::Map<const Eigen::Vector3d>(r + 3 * v);
}

void BlockJacobi::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (z.size() != r.size()) z.resize(r.size());
  parallelFor<Index>(0, static_cast<Index>(inverse_.size()), 256, [&](const auto& range) {
    applyToNodes(range.begin(), range.end(), r.data(), z.data());
  });
}

void SpringGaussSeidel::setup(const SparseMatrix& A) {
  jacobi_.setup(A);
  order_.clear();
  starts_.assign(1, 0);
  incidences_.clear();
  if (!coupling_ || coupling_->empty()) return;
  // Each touched node's springs (held nodes left the springs' entries).
  std::vector<std::vector<Incidence>> byNode;
  std::vector<Index> slot(static_cast<std::size_t>(A.rows() / 3), -1);
  for (std::size_t k = 0; k < coupling_->size(); ++k)
    for (const CouplingSprings::Entry& e : coupling_->entries(k)) {
      Index& at = slot[static_cast<std::size_t>(e.node)];
      if (at < 0) {
        at = static_cast<Index>(order_.size());
        order_.push_back(e.node);
        byNode.emplace_back();
      }
      byNode[static_cast<std::size_t>(at)].push_back({k, e.weight});
    }
  for (const std::vector<Incidence>& list : byNode) {
    incidences_.insert(incidences_.end(), list.begin(), list.end());
    starts_.push_back(incidences_.size());
  }
  along_.assign(coupling_->size(), 0.0);
  forward_.resize(order_.size());
}

void SpringGaussSeidel::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  jacobi_.apply(r, z);
  if (order_.empty()) return;
  const CouplingSprings& springs = *coupling_;
  // Forward: (D + L) y = r on the touched nodes, L the springs' blocks to
  // nodes swept before.
  std::fill(along_.begin(), along_.end(), 0.0);
  for (std::size_t i = 0; i < order_.size(); ++i) {
    Eigen::Vector3d rhs = r.segment<3>(3 * order_[i]);
    for (std::size_t at = starts_[i]; at != starts_[i + 1]; ++at) {
      const Incidence& e = incidences_[at];
      rhs -=
          springs.stiffness(e.spring) * e.weight * along_[e.spring] * springs.direction(e.spring);
    }
    forward_[i] = jacobi_.inverse(order_[i]) * rhs;
    for (std::size_t at = starts_[i]; at != starts_[i + 1]; ++at) {
      const Incidence& e = incidences_[at];
      along_[e.spring] += e.weight * springs.direction(e.spring).dot(forward_[i]);
    }
  }
  // Backward: (D + U) z = D y, U = L^T: z = y - D^-1 U z, nodes after.
  std::fill(along_.begin(), along_.end(), 0.0);
  for (std::size_t i = order_.size(); i-- > 0;) {
    Eigen::Vector3d later = Eigen::Vector3d::Zero();
    for (std::size_t at = starts_[i]; at != starts_[i + 1]; ++at) {
      const Incidence& e = incidences_[at];
      later +=
          springs.stiffness(e.spring) * e.weight * along_[e.spring] * springs.direction(e.spring);
    }
    const Eigen::Vector3d value = forward_[i] - jacobi_.inverse(order_[i]) * later;
    z.segment<3>(3 * order_[i]) = value;
    for (std::size_t at = starts_[i]; at != starts_[i + 1]; ++at) {
      const Incidence& e = incidences_[at];
      along_[e.spring] += e.weight * springs.direction(e.spring).dot(value);
    }
  }
}

struct MultigridPreconditioner::Impl {
  std::vector<GalerkinStream> streams;  // built on the first Galerkin setup() after a change
  std::vector<SweepOrder> sweeps;       // per level, once per pattern
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> coarsest;
  // One of the two is used (setSinglePrecision); apply() writes its scratch.
  mutable Cycle<float> single;
  mutable Cycle<double> twin;

  template <typename Scalar>
  Cycle<Scalar>& cycle() const {
    if constexpr (std::is_same_v<Scalar, float>)
      return single;
    else
      return twin;
  }
};

namespace {

struct Smoothing {
  MultigridSmoother smoother;
  int degree;      // Chebyshev
  int sweepCount;  // Gauss-Seidel
};

// One V-cycle z = M^-1 r in Scalar (see the class comment).
template <typename Scalar>
void vCycle(Cycle<Scalar>& s, const std::vector<SparseMatrix>& nodal,
            const std::vector<SparseMatrix>& restrictions, const std::vector<SweepOrder>& sweeps,
            const Smoothing& smoothing,
            const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& coarsest,
            const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  const std::size_t last = s.blocks.size() - 1;
  const int sweepCount = smoothing.sweepCount;
  const bool chebyshev = smoothing.smoother == MultigridSmoother::Chebyshev;
  s.b[0] = r.cast<Scalar>();
  // Down: pre-smooth from zero, restrict the residual.
  for (std::size_t l = 0; l < last; ++l) {
    s.b[l + 1].resize(3 * restrictions[l].rows());
    if (chebyshev) {
      chebyshevFromZero(s, l, smoothing.degree);
      multiplyNodalBlocks(restrictions[l], s.r[l].data(), s.b[l + 1].data());
      continue;
    }
    s.x[l].resize(s.b[l].size());
    s.r[l].resize(s.b[l].size());
    forwardSweepFromZero(s.blocks[l], s.inverseDiagonals[l], sweeps[l], s.b[l].data(),
                         s.x[l].data());
    for (int i = 1; i < sweepCount; ++i)
      blockGaussSeidel(s.blocks[l], s.inverseDiagonals[l], sweeps[l], s.b[l].data(), s.x[l].data(),
                       true);
    if (sweepCount == 1) {
      residualAfterSweepFromZero(s.blocks[l], s.x[l].data(), s.r[l].data());
    } else {
      multiply(s.blocks[l], s.x[l], s.r[l]);
      s.r[l] = s.b[l] - s.r[l];
    }
    multiplyNodalBlocks(restrictions[l], s.r[l].data(), s.b[l + 1].data());
  }
  s.x[last] = coarsest.solve(s.b[last].template cast<double>()).template cast<Scalar>();
  // Up: prolongate the correction, post-smooth (Gauss-Seidel backwards:
  // the cycle stays symmetric).
  for (std::size_t l = last; l-- > 0;) {
    if (chebyshev) {
      multiplyNodalBlocks(nodal[l], s.x[l + 1].data(), s.d[l].data());
      s.x[l] += s.d[l];
      chebyshevAfterCorrection(s, l, smoothing.degree);
      continue;
    }
    multiplyNodalBlocks(nodal[l], s.x[l + 1].data(), s.r[l].data());
    s.x[l] += s.r[l];
    for (int i = 0; i < sweepCount; ++i)
      blockGaussSeidel(s.blocks[l], s.inverseDiagonals[l], sweeps[l], s.b[l].data(), s.x[l].data(),
                       false);
  }
  z = s.x[0].template cast<double>();
}

}  // namespace

MultigridPreconditioner::MultigridPreconditioner(std::vector<SparseMatrix> nodalProlongations,
                                                 int smoothingSweeps)
    : prolongations_(std::move(nodalProlongations)),
      sweeps_(smoothingSweeps),
      impl_(std::make_shared<Impl>()) {
  setFixedNodesPerLevel({});
}

MultigridPreconditioner::~MultigridPreconditioner() = default;

void MultigridPreconditioner::setFixedNodesPerLevel(
    const std::vector<std::vector<char>>& fixedPerLevel) {
  auto fixed = [&](std::size_t level, int node) {
    return level < fixedPerLevel.size() && !fixedPerLevel[level].empty() &&
           fixedPerLevel[level][static_cast<std::size_t>(node)];
  };
  nodal_ = prolongations_;
  for (std::size_t l = 0; l < nodal_.size(); ++l) {
    // Fixed fine nodes must not receive coarse corrections, nor fixed coarse
    // nodes pass any on.
    SparseMatrix& P = nodal_[l];
    for (int row = 0; row < P.outerSize(); ++row)
      for (SparseMatrix::InnerIterator it(P, row); it; ++it)
        if (fixed(l, row) || fixed(l + 1, static_cast<int>(it.col()))) it.valueRef() = 0;
    P.prune(0.0);
  }
  restrictions_.clear();
  for (const SparseMatrix& P : nodal_) restrictions_.push_back(P.transpose());
  impl_->streams.clear();
  impl_->sweeps.clear();
  setupsSinceCoarse_ = 0;
}

void MultigridPreconditioner::setCoarseReuse(int setups) {
  reuse_ = std::max(1, setups);
}

bool MultigridPreconditioner::takeCoarseTurn() {
  const bool due = coarseDue();
  setupsSinceCoarse_ = (setupsSinceCoarse_ + 1) % reuse_;
  return due;
}

void MultigridPreconditioner::setup(const SparseMatrix& A) {
  // Level 0 is A itself (not copied: the caller keeps it alive while solving).
  levels_.resize(nodal_.size() + 1);
  levels_[0] = &A;
  const bool build = impl_->streams.empty();  // first setup for this pattern
  if (!takeCoarseTurn() && !build) {
    // Coarse operators from an earlier system: still an SPD preconditioner
    // of this one, and CG still solves this system to the tolerance.
    prepareLevels(levels_.size());
    return;
  }
  if (build && !hasNodeBlocks(A))  // the streams read blocks
    throw Error("multigrid: the system is not in the node-block layout");
  galerkin_.resize(nodal_.size());
  for (std::size_t l = 0; l < nodal_.size(); ++l) {
    if (build) impl_->streams.emplace_back(level(l), nodal_[l]);
    impl_->streams[l].compute(level(l), galerkin_[l]);
    levels_[l + 1] = &galerkin_[l];
  }
  prepareLevels(1);
}

void MultigridPreconditioner::setup(const SparseMatrix& A,
                                    const std::vector<SparseMatrix>& coarse) {
  if (coarse.size() != nodal_.size())
    throw Error("multigrid: one coarse operator per coarse level is needed");
  levels_.resize(nodal_.size() + 1);
  levels_[0] = &A;
  for (std::size_t l = 0; l < coarse.size(); ++l) levels_[l + 1] = &coarse[l];
  prepareLevels(takeCoarseTurn() ? 1 : levels_.size());
}

void MultigridPreconditioner::setSmoother(MultigridSmoother smoother, int degree) {
  if (degree < 1) throw Error("multigrid: the Chebyshev smoother's degree must be at least 1");
  smoother_ = smoother;
  degree_ = degree;
  impl_->sweeps.clear();  // the next setup prepares every level (and its eigenvalue) anew
}

void MultigridPreconditioner::setSinglePrecision(bool single) {
  single_ = single;
  impl_->sweeps.clear();  // the next setup prepares the chosen cycle from scratch
}

void MultigridPreconditioner::prepareLevels(std::size_t firstChanged) {
  const bool build = impl_->sweeps.empty();  // first setup for these patterns and precision
  if (build) {
    firstChanged = 1;  // every level is new to the cycle
    for (const SparseMatrix* A : levels_) {
      if (!hasNodeBlocks(*A)) throw Error("multigrid: a level is not in the node-block layout");
      impl_->sweeps.push_back(sweepOrder(*A));
    }
    impl_->single.resize(single_ ? levels_.size() : 0);
    impl_->twin.resize(single_ ? 0 : levels_.size());
  }
  // (With Chebyshev smoothing, each level's new matrix gets its eigenvalue.)
  auto prepare = [&](std::size_t l) {
    if (l + 1 == levels_.size()) return;  // the coarsest is factorized below instead
    const bool chebyshev = smoother_ == MultigridSmoother::Chebyshev;
    if (single_) {
      impl_->single.prepare(level(l), l, impl_->sweeps[l], !chebyshev);
      if (chebyshev) estimateLargestEigenvalue(impl_->single, l);
    } else {
      impl_->twin.prepare(level(l), l, impl_->sweeps[l], !chebyshev);
      if (chebyshev) estimateLargestEigenvalue(impl_->twin, l);
    }
  };
  prepare(0);
  // (With one level the coarsest is the system itself: always new.)
  if (firstChanged >= levels_.size() && levels_.size() > 1) return;
  for (std::size_t l = std::max<std::size_t>(firstChanged, 1); l < levels_.size(); ++l) prepare(l);
  // With Dirichlet rows removed from P, columns of P can become linearly
  // dependent and the coarsest operator singular. Its null vectors v have
  // P v = 0 and never reach the fine grid, so a tiny shift that makes the
  // factorization possible changes nothing that matters.
  const SparseMatrix& coarsest = level(levels_.size() - 1);
  impl_->coarsest.setShift(1e-12 * coarsest.diagonal().cwiseAbs().maxCoeff());
  const Eigen::SparseMatrix<double> columnMajor(coarsest);
  if (build) impl_->coarsest.analyzePattern(columnMajor);  // the ordering, once per pattern
  impl_->coarsest.factorize(columnMajor);
  if (impl_->coarsest.info() != Eigen::Success)
    throw Error("multigrid: the coarsest operator could not be factorized");
}

void MultigridPreconditioner::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const Smoothing smoothing{smoother_, degree_, sweeps_};
  if (single_)
    vCycle(impl_->single, nodal_, restrictions_, impl_->sweeps, smoothing, impl_->coarsest, r, z);
  else
    vCycle(impl_->twin, nodal_, restrictions_, impl_->sweeps, smoothing, impl_->coarsest, r, z);
}

}  // namespace tetskin
