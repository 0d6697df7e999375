// SPDX-License-Identifier: AGPL-3.0-or-later
#include "GalerkinStream.h"

#include <algorithm>

#include "tetskin/core/Parallel.h"

namespace tetskin {
namespace {

// Value index of entry (row, col) in a compressed row-major matrix.
int slot(const SparseMatrix& m, int row, int col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[row];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[row + 1];
  return static_cast<int>(std::lower_bound(begin, end, col) - m.innerIndexPtr());
}

}  // namespace

GalerkinStream::GalerkinStream(const SparseMatrix& fine, const SparseMatrix& nodalP) {
  const int fineNodes = static_cast<int>(nodalP.rows());
  const int coarseNodes = static_cast<int>(nodalP.cols());
  struct Term {
    long long target;  // I * coarseNodes + J
    int source;        // slot of fine (3i, 3j)
    int sourceStride;
    double weight;
  };
  std::vector<Term> terms;
  reached_.assign(static_cast<std::size_t>(coarseNodes), 0);
  for (int i = 0; i < fineNodes; ++i)
    for (SparseMatrix::InnerIterator pi(nodalP, i); pi; ++pi)
      reached_[static_cast<std::size_t>(pi.col())] = 1;
  // Fine blocks: every third row, every third column of a row.
  for (int i = 0; i < fineNodes; ++i) {
    const int row = 3 * i;
    const int rowStride = fine.outerIndexPtr()[row + 1] - fine.outerIndexPtr()[row];
    for (int s = fine.outerIndexPtr()[row]; s < fine.outerIndexPtr()[row + 1]; s += 3) {
      const int j = fine.innerIndexPtr()[s] / 3;
      for (SparseMatrix::InnerIterator pi(nodalP, i); pi; ++pi)
        for (SparseMatrix::InnerIterator pj(nodalP, j); pj; ++pj)
          terms.push_back({static_cast<long long>(pi.col()) * coarseNodes + pj.col(), s, rowStride,
                           pi.value() * pj.value()});
    }
  }
  for (int I = 0; I < coarseNodes; ++I)  // diagonal blocks always exist
    terms.push_back({static_cast<long long>(I) * coarseNodes + I, -1, 0, 0.0});
  std::sort(terms.begin(), terms.end(),
            [](const Term& a, const Term& b) { return a.target < b.target; });

  std::vector<Eigen::Triplet<double, int>> triplets;
  for (std::size_t t = 0; t < terms.size(); ++t) {
    if (t > 0 && terms[t].target == terms[t - 1].target) continue;
    const int I = static_cast<int>(terms[t].target / coarseNodes),
              J = static_cast<int>(terms[t].target % coarseNodes);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) triplets.emplace_back(3 * I + a, 3 * J + b, 0.0);
  }
  coarse_.resize(3 * coarseNodes, 3 * coarseNodes);
  coarse_.setFromTriplets(triplets.begin(), triplets.end());
  coarse_.makeCompressed();

  diagonal_.assign(static_cast<std::size_t>(coarseNodes), -1);
  for (std::size_t t = 0; t < terms.size(); ++t) {
    const bool first = t == 0 || terms[t].target != terms[t - 1].target;
    const int I = static_cast<int>(terms[t].target / coarseNodes),
              J = static_cast<int>(terms[t].target % coarseNodes);
    if (first) {
      offsets_.push_back(static_cast<int>(sources_.size()));
      targets_.push_back(slot(coarse_, 3 * I, 3 * J));
      coarseRowStride_.push_back(coarse_.outerIndexPtr()[3 * I + 1] -
                                 coarse_.outerIndexPtr()[3 * I]);
      if (I == J) diagonal_[static_cast<std::size_t>(I)] = static_cast<int>(targets_.size()) - 1;
    }
    if (terms[t].source >= 0) {
      sources_.push_back(terms[t].source);
      weights_.push_back(terms[t].weight);
      fineRowStride_.push_back(terms[t].sourceStride);
    }
  }
  offsets_.push_back(static_cast<int>(sources_.size()));
}

void GalerkinStream::compute(const SparseMatrix& fine, SparseMatrix& coarse) const {
  if (coarse.nonZeros() != coarse_.nonZeros()) coarse = coarse_;
  const double* a = fine.valuePtr();
  double* c = coarse.valuePtr();
  parallelFor<std::size_t>(0, targets_.size(), 256, [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      double block[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (int k = offsets_[t]; k < offsets_[t + 1]; ++k) {
        const double w = weights_[static_cast<std::size_t>(k)];
        const double* s = a + sources_[static_cast<std::size_t>(k)];
        const int stride = fineRowStride_[static_cast<std::size_t>(k)];
        for (int r = 0; r < 3; ++r)
          for (int q = 0; q < 3; ++q) block[3 * r + q] += w * s[r * stride + q];
      }
      double* out = c + targets_[t];
      const int stride = coarseRowStride_[t];
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) out[r * stride + q] = block[3 * r + q];
    }
  });
  for (std::size_t I = 0; I < reached_.size(); ++I)
    if (!reached_[I]) {
      double* out = c + targets_[static_cast<std::size_t>(diagonal_[I])];
      const int stride = coarseRowStride_[static_cast<std::size_t>(diagonal_[I])];
      for (int r = 0; r < 3; ++r) out[r * stride + r] = 1.0;
    }
}

}  // namespace tetskin
