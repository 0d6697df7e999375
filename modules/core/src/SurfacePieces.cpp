// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/SurfacePieces.h"

#include <algorithm>
#include <numeric>

namespace tetskin {
namespace {

// Assigns the triangles in order[begin, end) to pieces [firstPiece,
// firstPiece + pieces), splitting at the longest side of their centroids'
// box.
void bisect(const Points3& centroids, std::vector<Index>& order, Index begin, Index end,
            int firstPiece, int pieces, std::vector<int>& pieceOfTriangle) {
  if (pieces == 1) {
    for (Index i = begin; i < end; ++i)
      pieceOfTriangle[static_cast<std::size_t>(order[i])] = firstPiece;
    return;
  }
  Eigen::RowVector3d lo = centroids.row(order[begin]), hi = lo;
  for (Index i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(centroids.row(order[i]));
    hi = hi.cwiseMax(centroids.row(order[i]));
  }
  Eigen::Index axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int leftPieces = pieces / 2;
  // The left side's share of the triangles, rounded so that every piece
  // ends up with floor or ceil of count / pieces.
  const Index count = end - begin;
  const Index middle = begin + count * leftPieces / pieces;
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](Index a, Index b) {
                     const double ca = centroids(a, axis), cb = centroids(b, axis);
                     return ca < cb || (ca == cb && a < b);  // (ties: deterministic)
                   });
  bisect(centroids, order, begin, middle, firstPiece, leftPieces, pieceOfTriangle);
  bisect(centroids, order, middle, end, firstPiece + leftPieces, pieces - leftPieces,
         pieceOfTriangle);
}

}  // namespace

std::vector<int> surfacePieces(const Points3& vertices, const Triangles& triangles, int pieces) {
  const Index count = triangles.rows();
  std::vector<int> pieceOfTriangle(static_cast<std::size_t>(count), 0);
  pieces = static_cast<int>(std::clamp<Index>(pieces, 1, std::max<Index>(count, 1)));
  if (pieces == 1) return pieceOfTriangle;
  Points3 centroids(count, 3);
  for (Index t = 0; t < count; ++t)
    centroids.row(t) = (vertices.row(triangles(t, 0)) + vertices.row(triangles(t, 1)) +
                        vertices.row(triangles(t, 2))) /
                       3.0;
  std::vector<Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), Index{0});
  bisect(centroids, order, 0, count, 0, pieces, pieceOfTriangle);
  return pieceOfTriangle;
}

std::vector<SurfacePiece> splitSurface(Index vertexCount, const Triangles& triangles,
                                       const std::vector<int>& pieceOfTriangle) {
  const int pieces = pieceOfTriangle.empty()
                         ? 1
                         : *std::max_element(pieceOfTriangle.begin(), pieceOfTriangle.end()) + 1;
  std::vector<SurfacePiece> out(static_cast<std::size_t>(pieces));
  for (Index t = 0; t < triangles.rows(); ++t)
    out.at(static_cast<std::size_t>(pieceOfTriangle[static_cast<std::size_t>(t)]))
        .triangles.push_back(t);
  // A vertex belongs to every piece one of its triangles is in; marked per
  // piece so each list comes out sorted without a sort. (-1: used by no
  // triangle, so piece 0's; -2: used, by no piece marked yet.)
  std::vector<int> mark(static_cast<std::size_t>(vertexCount), -1);
  for (Index i = 0; i < triangles.size(); ++i)
    mark.at(static_cast<std::size_t>(triangles.data()[i])) = -2;
  for (int p = 0; p < pieces; ++p) {
    SurfacePiece& piece = out[static_cast<std::size_t>(p)];
    for (Index t : piece.triangles)
      for (int c = 0; c < 3; ++c) mark[static_cast<std::size_t>(triangles(t, c))] = p;
    for (Index v = 0; v < vertexCount; ++v) {
      const int m = mark[static_cast<std::size_t>(v)];
      if (m == p || (p == 0 && m == -1)) piece.vertices.push_back(v);
    }
  }
  return out;
}

}  // namespace tetskin
