// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A system in the node-block layout (LinearSolvers.h) copied into its 3x3
// blocks for CG's product, its hot loop. In the row-major SparseMatrix the
// nine entries of a block lie in three rows and its product is scalar code;
// here each block is stored column by column, every column padded to four
// entries, so a block times a 3-vector is three 4-wide multiply-adds: one
// AVX2 instruction each where the CPU has AVX2 and FMA (that kernel is
// chosen at run time), two SSE2 ones in the baseline kernel. On the
// 12.7k-element level the AVX2 product takes about 0.6 of the SparseMatrix
// one and the copy, once per step, about 1.5 products (simulation_bench
// prints both in one run).

#include <vector>

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

class NodeBlockMatrix {
 public:
  NodeBlockMatrix() = default;
  explicit NodeBlockMatrix(const SparseMatrix& A) { assign(A); }
  // Copies A, which must be square, compressed and in the node-block layout
  // (its row lengths are checked here; the column triples, which a
  // CorotatedFem pattern always has, are not). Reuses the storage when the
  // shape is unchanged.
  void assign(const SparseMatrix& A);

  Index rows() const { return 3 * nodeCount(); }
  Index nodeCount() const { return static_cast<Index>(blockStarts_.size()) - 1; }
  Index blockCount() const { return static_cast<Index>(columns_.size()); }

  // Storage, for the product kernel: node v's blocks are
  // blockStarts()[v] .. blockStarts()[v+1]-1; block k's first column is
  // columns()[k] and its entries are values()[12 k + 4 c + a] = A(3v+a, columns()[k]+c)
  // for a, c < 3 (entry 4 c + 3 is zero).
  const std::vector<int>& blockStarts() const { return blockStarts_; }
  const std::vector<int>& columns() const { return columns_; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<int> blockStarts_{0};
  std::vector<int> columns_;
  std::vector<double> values_;
};

// Which kernel multiplies: the fastest this CPU runs (AVX2 where it has
// AVX2 and FMA, see usesAvx2Product()) or the baseline one, which runs on
// every CPU (for tests and benchmarks of both on one machine).
enum class BlockProduct { Fastest, Baseline };
bool usesAvx2Product();

// y = A x, nodes in parallel.
void multiply(const NodeBlockMatrix& A, const Eigen::VectorXd& x, Eigen::VectorXd& y,
              BlockProduct kernel = BlockProduct::Fastest);

}  // namespace tetskin
