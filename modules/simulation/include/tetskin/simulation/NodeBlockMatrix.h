// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A system in the node-block layout (LinearSolvers.h) copied into its 3x3
// blocks for CG's product, its hot loop. In the row-major SparseMatrix the
// nine entries of a block lie in three rows and its product is scalar code;
// here each block is stored column by column, nine entries, and a block
// times a 3-vector is three 4-wide multiply-adds of a column loaded with the
// entry after it (the fourth lane, left out of the sums): one AVX2
// instruction each where the CPU has AVX2 and FMA (that kernel is chosen at
// run time), two SSE2 ones in the baseline kernel. Unpadded, a block is 9
// entries where a padded one was 12: the products and sweeps that bound
// the solvers stream their matrices from memory, so a quarter fewer bytes. On the
// 12.7k-element level the AVX2 product takes about 0.6 of the SparseMatrix
// one and the copy, once per step, about 1.5 products (simulation_bench
// prints both in one run). The multigrid's V-cycle keeps float copies in the
// same layout (each node's blocks in its sweep's order): there a block
// column is one 4-wide SSE operation everywhere.

#include <vector>

#include "tetskin/simulation/CorotatedFem.h"
#include "tetskin/simulation/SimdKernel.h"

namespace tetskin {

// The cheap half of the node-block layout check (hasNodeBlocks() in
// LinearSolvers.h), O(rows): A square, compressed, 3 dofs per node, and the
// three rows of every node equally long, a whole number of blocks. When it
// fails, *badNode (if given) is the first node whose rows are not, or -1
// when the shape is wrong.
bool hasNodeRowLengths(const SparseMatrix& A, Index* badNode = nullptr);

// Scalar double for CG's product, float for the multigrid's V-cycle.
template <typename Scalar>
class BasicNodeBlockMatrix {
 public:
  BasicNodeBlockMatrix() = default;
  explicit BasicNodeBlockMatrix(const SparseMatrix& A) { assign(A); }
  // Copies A (rounded to Scalar), which must be square, compressed and in
  // the node-block layout (its row lengths are checked here; the column
  // triples, which a CorotatedFem pattern always has, are not). Reuses the
  // storage when the shape is unchanged.
  void assign(const SparseMatrix& A);
  // The same copy with each node v's blocks in the order of a sweep that
  // visits the nodes by ascending `rank` (one per node, distinct among
  // coupled nodes): first the blocks of the nodes ranked before v, then
  // v's own diagonal block, then those of the nodes ranked after it (by
  // column within each group). A sweep from zero then reads only the
  // first group, and the residual after it only the last
  // (LinearSolvers.cpp).
  void assignInSweepOrder(const SparseMatrix& A, const std::vector<int>& rank);

  Index rows() const { return 3 * nodeCount(); }
  Index nodeCount() const { return static_cast<Index>(blockStarts_.size()) - 1; }
  Index blockCount() const { return static_cast<Index>(columns_.size()); }

  // Storage, for the kernels: node v's blocks are
  // blockStarts()[v] .. blockStarts()[v+1]-1; block k's first column is
  // columns()[k] and its entries are
  // values()[kBlockEntries k + 3 c + a] = A(3v+a, columns()[k]+c) for a, c < 3;
  // values() holds one zero after the last block, so that every column can
  // be loaded four entries wide.
  static constexpr int kBlockEntries = 9;
  const std::vector<int>& blockStarts() const { return blockStarts_; }
  const std::vector<int>& columns() const { return columns_; }
  const std::vector<Scalar>& values() const { return values_; }

  // After assignInSweepOrder(): node v's blocks of earlier-ranked nodes are
  // blockStarts()[v] .. laterBlocks(v)-1 less its diagonal block, the last
  // of them where there is one; those of later-ranked nodes laterBlocks(v)
  // .. blockStarts()[v+1]-1. (After assign(), in column order, -1.)
  int laterBlocks(Index v) const {
    return laterStarts_.empty() ? -1 : laterStarts_[static_cast<std::size_t>(v)];
  }

  // Node v's diagonal block (zero where the pattern has none): its row's
  // blocks are contiguous, so this reads one short column list and one
  // block, where the sparse matrix needs a search in one row and entries
  // from three.
  Eigen::Matrix<Scalar, 3, 3> diagonalBlock(Index v) const;

 private:
  std::vector<int> blockStarts_{0};
  std::vector<int> columns_;
  std::vector<Scalar> values_;
  std::vector<int> laterStarts_;  // per node, in sweep order only (laterBlocks())
  // The shape of A (row lengths checked) into blockStarts_, columns_, values_.
  void allocate(const SparseMatrix& A);
};

using NodeBlockMatrix = BasicNodeBlockMatrix<double>;
using FloatNodeBlockMatrix = BasicNodeBlockMatrix<float>;

// y = A x, nodes in parallel (double: the kernel as chosen; float: one
// 4-wide SSE kernel, for every CPU).
void multiply(const NodeBlockMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y,
              SimdKernel kernel = SimdKernel::Fastest);
void multiply(const FloatNodeBlockMatrix& A, const Eigen::VectorXf& x, Eigen::VectorXf& y);

// Several vectors side by side, one per column; row-major, so the values of
// one dof are adjacent.
using DenseRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
// Y = A X for up to kMaxProductColumns columns in one pass over A: A is read
// once for all of them, and each block column, one 4-wide vector, multiplies
// the k values of one dof of X (the kernel chosen like the single product's).
constexpr int kMaxProductColumns = 16;
void multiply(const NodeBlockMatrix& A, const DenseRows& X, DenseRows& Y,
              SimdKernel kernel = SimdKernel::Fastest);

// Block k's three columns as `Lanes` vectors of four Scalar, loaded
// unaligned (memcpy); the fourth lane holds the entry after the column (the
// next column's or block's first), which the kernels' sums leave out.
// Always inlined, so that in a caller compiled for AVX2 they are AVX2 loads.
template <typename Lanes, typename Scalar>
[[gnu::always_inline]] inline void loadBlockColumns(const BasicNodeBlockMatrix<Scalar>& A, int k,
                                                    Lanes columns[3]) {
  const Scalar* block = A.values().data() + BasicNodeBlockMatrix<Scalar>::kBlockEntries *
                                                static_cast<std::ptrdiff_t>(k);
  for (int c = 0; c < 3; ++c) __builtin_memcpy(&columns[c], block + 3 * c, sizeof(Lanes));
}

// sums = sum of A_vu x_u over blocks first .. last-1 of A (some or all of
// node v's), leaving out column `skipColumn` (a node's first dof, e.g. 3 v
// for Gauss-Seidel; -1 for none), with each block column one `Lanes`
// vector of four Scalar (GCC's vector extension: left to itself the
// compiler computes the three rows as 2 + 1 lanes). Inline for callers with
// their own loop over nodes; always inlined, so that in a caller compiled
// for AVX2 it is AVX2 code.
template <typename Lanes, typename Scalar>
[[gnu::always_inline]] inline void blockRangeSumLanes(const BasicNodeBlockMatrix<Scalar>& A,
                                                      int first, int last, const Scalar* x,
                                                      int skipColumn, Scalar sums[3]) {
  Lanes total = {0, 0, 0, 0};
  const int* columns = A.columns().data();
  for (int k = first; k < last; ++k) {
    if (columns[k] == skipColumn) continue;
    const Scalar* xc = x + columns[k];
    Lanes c[3];
    loadBlockColumns(A, k, c);
    total += c[0] * xc[0] + c[1] * xc[1] + c[2] * xc[2];
  }
  for (int a = 0; a < 3; ++a) sums[a] = total[a];
}

// The same over all of node v's blocks.
template <typename Lanes, typename Scalar>
[[gnu::always_inline]] inline void blockRowSumLanes(const BasicNodeBlockMatrix<Scalar>& A, Index v,
                                                    const Scalar* x, int skipColumn,
                                                    Scalar sums[3]) {
  const auto node = static_cast<std::size_t>(v);
  blockRangeSumLanes<Lanes>(A, A.blockStarts()[node], A.blockStarts()[node + 1], x, skipColumn,
                            sums);
}

// The range kernels of the products and sweeps. Float: four lanes are one
// SSE register on every x86-64 CPU.
inline void blockRangeSum(const FloatNodeBlockMatrix& A, int first, int last, const float* x,
                          int skipColumn, float sums[3]) {
  using Float4 = float __attribute__((vector_size(16)));
  blockRangeSumLanes<Float4>(A, first, last, x, skipColumn, sums);
}

// Double, baseline: four double lanes would be two SSE2 registers, which
// measured slower than the compiler's own vectorization of this loop (the
// AVX2 product uses blockRowSumLanes with one AVX register).
inline void blockRangeSum(const NodeBlockMatrix& A, int first, int last, const double* x,
                          int skipColumn, double sums[3]) {
  double total[3] = {0, 0, 0};
  const int* columns = A.columns().data();
  const double* values = A.values().data();
  for (int k = first; k < last; ++k) {
    if (columns[k] == skipColumn) continue;
    const double* block = values + NodeBlockMatrix::kBlockEntries * static_cast<std::ptrdiff_t>(k);
    const double* xc = x + columns[k];
    for (int a = 0; a < 3; ++a)
      total[a] += block[a] * xc[0] + block[3 + a] * xc[1] + block[6 + a] * xc[2];
  }
  for (int a = 0; a < 3; ++a) sums[a] = total[a];
}

// The row kernels: all of node v's blocks.
template <typename Scalar>
inline void blockRowSum(const BasicNodeBlockMatrix<Scalar>& A, Index v, const Scalar* x,
                        int skipColumn, Scalar sums[3]) {
  const auto node = static_cast<std::size_t>(v);
  blockRangeSum(A, A.blockStarts()[node], A.blockStarts()[node + 1], x, skipColumn, sums);
}

}  // namespace tetskin
