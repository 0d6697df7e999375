// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The coarse operator C = P^T A P of one multigrid level, computed as a
// precomputed stream (Georgii & Westermann 2008, "streaming Galerkin
// product"): with P a nodal prolongation (each weight times a 3x3 identity)
// and A's sparsity fixed, every 3x3 block of C is a weighted sum of 3x3
// blocks of A. The list of (source block, weight) per target block is built
// once; each time step is then one pass over it, parallel over target blocks.

#include <vector>

#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin {

class GalerkinStream {
 public:
  // `fine`: the fine operator's pattern (3x3 blocks per node pair);
  // `nodalP`: fine nodes x coarse nodes. The coarse pattern always holds
  // every diagonal block.
  GalerkinStream(const SparseMatrix& fine, const SparseMatrix& nodalP);

  // The coarse operator's pattern (values zero), as returned by compute().
  const SparseMatrix& pattern() const { return coarse_; }

  // C = P^T A P for A with the constructor's pattern; a coarse node no fine
  // node reaches gets an identity block (else C would be singular).
  void compute(const SparseMatrix& fine, SparseMatrix& coarse) const;

 private:
  SparseMatrix coarse_;
  // Per target block t: contributions [offsets[t], offsets[t+1]).
  std::vector<int> offsets_;
  std::vector<int> sources_;  // value index of the fine block's (0,0) entry
  std::vector<double> weights_;
  std::vector<int> targets_;          // value index of the coarse block's (0,0) entry
  std::vector<int> fineRowStride_;    // per source: offset to the block's next row
  std::vector<int> coarseRowStride_;  // per target
  std::vector<char> reached_;         // per coarse node: some fine node maps to it
  std::vector<int> diagonal_;         // per coarse node: target index of its diagonal block
};

}  // namespace tetskin
