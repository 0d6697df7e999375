// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/NodeBlockMatrix.h"

#include <algorithm>
#include <string>
#include <utility>

#include "SimdTarget.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {

bool hasNodeRowLengths(const SparseMatrix& A, Index* badNode) {
  if (badNode) *badNode = -1;
  if (A.rows() != A.cols() || A.rows() % 3 != 0 || !A.isCompressed()) return false;
  const int* outer = A.outerIndexPtr();
  for (Index v = 0; v < A.rows() / 3; ++v) {
    const int length = outer[3 * v + 1] - outer[3 * v];
    if (length % 3 != 0 || outer[3 * v + 2] - outer[3 * v + 1] != length ||
        outer[3 * v + 3] - outer[3 * v + 2] != length) {
      if (badNode) *badNode = v;
      return false;
    }
  }
  return true;
}

template <typename Scalar>
void BasicNodeBlockMatrix<Scalar>::allocate(const SparseMatrix& A) {
  Index badNode = -1;
  if (!hasNodeRowLengths(A, &badNode))
    throw Error(badNode < 0 ? "node-block matrix: the system is not square, compressed and 3 "
                              "dofs per node"
                            : "node-block matrix: the rows of node " + std::to_string(badNode) +
                                  " are not in the node-block layout");
  const Index nodes = A.rows() / 3;
  const int* outer = A.outerIndexPtr();
  blockStarts_.resize(static_cast<std::size_t>(nodes) + 1);
  blockStarts_[0] = 0;
  for (Index v = 0; v < nodes; ++v)
    blockStarts_[static_cast<std::size_t>(v) + 1] =
        blockStarts_[static_cast<std::size_t>(v)] + (outer[3 * v + 1] - outer[3 * v]) / 3;
  const auto blocks = static_cast<std::size_t>(blockStarts_.back());
  columns_.resize(blocks);
  values_.resize(kBlockEntries * blocks + 1);  // (the zero after the last block)
  values_.back() = 0;
}

namespace {

// Block b of node v's rows of A into slot `slot` of the copy: its first
// column and its entries column by column.
template <typename Scalar>
[[gnu::always_inline]] inline void copyBlock(const SparseMatrix& A, Index v, int b, int* columns,
                                             Scalar* values, std::size_t slot) {
  const int* outer = A.outerIndexPtr();
  columns[slot] = A.innerIndexPtr()[outer[3 * v] + 3 * b];
  Scalar* block = values + BasicNodeBlockMatrix<Scalar>::kBlockEntries * slot;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a)
      block[3 * c + a] = static_cast<Scalar>(A.valuePtr()[outer[3 * v + a] + 3 * b + c]);
}

}  // namespace

template <typename Scalar>
void BasicNodeBlockMatrix<Scalar>::assign(const SparseMatrix& A) {
  allocate(A);
  laterStarts_.clear();
  parallelFor<Index>(0, nodeCount(), 256, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const int first = blockStarts_[static_cast<std::size_t>(v)];
      const int count = blockStarts_[static_cast<std::size_t>(v) + 1] - first;
      for (int b = 0; b < count; ++b)
        copyBlock(A, v, b, columns_.data(), values_.data(), static_cast<std::size_t>(first + b));
    }
  });
}

template <typename Scalar>
void BasicNodeBlockMatrix<Scalar>::assignInSweepOrder(const SparseMatrix& A,
                                                      const std::vector<int>& rank) {
  allocate(A);
  if (rank.size() != static_cast<std::size_t>(nodeCount()))
    throw Error("node-block matrix: the sweep ranks do not fit the matrix");
  laterStarts_.resize(static_cast<std::size_t>(nodeCount()));
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  parallelFor<Index>(0, nodeCount(), 256, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const auto node = static_cast<std::size_t>(v);
      const int first = blockStarts_[node];
      const int count = blockStarts_[node + 1] - first;
      const int own = rank[node];
      const int* columns = inner + outer[3 * v];
      auto ranked = [&](int b) { return rank[static_cast<std::size_t>(columns[3 * b] / 3)]; };
      // Earlier nodes, then v itself, then later ones, each group in column
      // order. The slots are counted first and chosen by arithmetic, not
      // branches: a neighbour is earlier or later about as often as not,
      // and branching on it made this copy 2.7 times as slow as assign() at
      // 109k elements in float (2.4 against 0.9 ms; now 1.3-1.5 against
      // 1.0-1.1).
      int earlier = 0, itself = 0;  // blocks of earlier nodes; of v (1, or 0 without one)
      for (int b = 0; b < count; ++b) {
        earlier += ranked(b) < own;
        itself += ranked(b) == own;
      }
      int nextEarlier = first, diagonal = first + earlier, nextLater = diagonal + itself;
      laterStarts_[node] = nextLater;
      for (int b = 0; b < count; ++b) {
        const int r = ranked(b);
        const auto isEarlier = static_cast<int>(r < own), isLater = static_cast<int>(r > own);
        const int slot =
            isEarlier * nextEarlier + isLater * nextLater + (1 - isEarlier - isLater) * diagonal;
        nextEarlier += isEarlier;
        nextLater += isLater;
        copyBlock(A, v, b, columns_.data(), values_.data(), static_cast<std::size_t>(slot));
      }
    }
  });
}

template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3> BasicNodeBlockMatrix<Scalar>::diagonalBlock(Index v) const {
  const auto node = static_cast<std::size_t>(v);
  const auto begin = columns_.begin() + blockStarts_[node];
  const auto end = columns_.begin() + blockStarts_[node + 1];
  // In column order a search; in sweep order the last block before the
  // later nodes' (v ranks after its earlier neighbours, before its later).
  const auto found = laterStarts_.empty() ? std::lower_bound(begin, end, static_cast<int>(3 * v))
                                          : columns_.begin() + (laterStarts_[node] - 1);
  Eigen::Matrix<Scalar, 3, 3> block = Eigen::Matrix<Scalar, 3, 3>::Zero();
  if (found < begin || found == end || *found != 3 * v) return block;
  const Scalar* entries = values_.data() + kBlockEntries * (found - columns_.begin());
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 3; ++a) block(a, c) = entries[3 * c + a];
  return block;
}

template class BasicNodeBlockMatrix<double>;
template class BasicNodeBlockMatrix<float>;

namespace {

// Baseline: blockRowSum's loop (SSE2).
void multiplyNodesBaseline(const NodeBlockMatrix& A, const double* x, double* y, Index firstNode,
                           Index lastNode) {
  for (Index v = firstNode; v != lastNode; ++v) blockRowSum(A, v, x, -1, y + 3 * v);
}

TETSKIN_AVX2_TARGET void multiplyNodesAvx2(const NodeBlockMatrix& A, const double* x, double* y,
                                           Index firstNode, Index lastNode) {
  using Double4 = double __attribute__((vector_size(32)));
  for (Index v = firstNode; v != lastNode; ++v) blockRowSumLanes<Double4>(A, v, x, -1, y + 3 * v);
}

using RowsKernel = void (*)(const NodeBlockMatrix&, const double*, double*, Index, Index);

RowsKernel rowsKernel(SimdKernel kernel) {
  return chooseKernel<RowsKernel>(kernel, multiplyNodesAvx2, multiplyNodesBaseline);
}

// Y's rows of node v for K columns: per block column c and column j of X,
// one multiply-add of the block column (four lanes, the fourth zero) with
// X(3u + c, j).
template <int K>
[[gnu::always_inline]] inline void multiplyNodeColumns(const NodeBlockMatrix& A, Index v,
                                                       const double* X, double* Y) {
  using Double4 = double __attribute__((vector_size(32)));
  Double4 sums[K] = {};
  const int* columns = A.columns().data();
  for (int k = A.blockStarts()[static_cast<std::size_t>(v)];
       k < A.blockStarts()[static_cast<std::size_t>(v) + 1]; ++k) {
    Double4 c[3];
    loadBlockColumns(A, k, c);
    const double* x = X + static_cast<std::ptrdiff_t>(columns[k]) * K;  // rows 3u .. 3u+2
    for (int j = 0; j < K; ++j) sums[j] += c[0] * x[j] + c[1] * x[K + j] + c[2] * x[2 * K + j];
  }
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < K; ++j) Y[(3 * v + a) * K + j] = sums[j][a];
}

template <int K>
void multiplyColumnsBaseline(const NodeBlockMatrix& A, const double* X, double* Y, Index firstNode,
                             Index lastNode) {
  for (Index v = firstNode; v != lastNode; ++v) multiplyNodeColumns<K>(A, v, X, Y);
}

template <int K>
TETSKIN_AVX2_TARGET void multiplyColumnsAvx2(const NodeBlockMatrix& A, const double* X, double* Y,
                                             Index firstNode, Index lastNode) {
  for (Index v = firstNode; v != lastNode; ++v) multiplyNodeColumns<K>(A, v, X, Y);
}

using ColumnsKernel = void (*)(const NodeBlockMatrix&, const double*, double*, Index, Index);

// The kernel for k = 1 .. kMaxProductColumns columns.
template <int... K>
ColumnsKernel columnsKernel(SimdKernel kernel, int k, std::integer_sequence<int, K...>) {
  constexpr ColumnsKernel avx2[] = {multiplyColumnsAvx2<K + 1>...};
  constexpr ColumnsKernel baseline[] = {multiplyColumnsBaseline<K + 1>...};
  return chooseKernel(kernel, avx2[k - 1], baseline[k - 1]);
}

template <typename Scalar>
void checkSizes(const BasicNodeBlockMatrix<Scalar>& A, const Eigen::Matrix<Scalar, -1, 1>& x,
                Eigen::Matrix<Scalar, -1, 1>& y) {
  if (x.size() != A.rows()) throw Error("node-block matrix: the vector does not fit the matrix");
  if (y.size() != A.rows()) y.resize(A.rows());
}

}  // namespace

void multiply(const NodeBlockMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y,
              SimdKernel kernel) {
  checkSizes(A, x, y);
  const RowsKernel rows = rowsKernel(kernel);
  parallelFor<Index>(0, A.nodeCount(), 256, [&](const auto& range) {
    rows(A, x.data(), y.data(), range.begin(), range.end());
  });
}

void multiply(const FloatNodeBlockMatrix& A, const Eigen::VectorXf& x, Eigen::VectorXf& y) {
  checkSizes(A, x, y);
  parallelFor<Index>(0, A.nodeCount(), 256, [&](const auto& range) {
    for (Index v = range.begin(); v != range.end(); ++v)
      blockRowSum(A, v, x.data(), -1, y.data() + 3 * v);
  });
}

void multiply(const NodeBlockMatrix& A, const DenseRows& X, DenseRows& Y, SimdKernel kernel) {
  const int k = static_cast<int>(X.cols());
  if (X.rows() != A.rows() || k > kMaxProductColumns)
    throw Error("node-block matrix: the vectors do not fit the matrix");
  Y.resize(A.rows(), k);
  if (k == 0) return;
  const ColumnsKernel rows =
      columnsKernel(kernel, k, std::make_integer_sequence<int, kMaxProductColumns>());
  parallelFor<Index>(0, A.nodeCount(), 128, [&](const auto& range) {
    rows(A, X.data(), Y.data(), range.begin(), range.end());
  });
}

}  // namespace tetskin
