// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A surface split into pieces for partitioned output (.pvtp) and
// data-parallel work: each triangle goes to one piece, pieces hold equal
// numbers of triangles (to one) and are compact in space, so a rank that
// reads one piece holds few points shared with other pieces. Recursive
// coordinate bisection of the triangles' centroids: each split cuts the
// longest side of the centroids' box at the count that gives each side its
// share of the pieces.

#include <vector>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/Types.h"

namespace tetskin {

// The number of pieces a surface is written in (`simulate`, `deform
// --pieces`, Simulation.record's `pieces`).
inline constexpr NumberOption kPiecesOption{
    "pieces",
    "--pieces",
    "",
    "the surface's pieces",
    "write the surface (each frame's) as a .pvtp in N compact pieces, cut the same in every "
    "frame, for ParaView's distributed server (mpiexec pvbatch, pvserver: each rank reads its "
    "own)",
    atLeast(1),
    1};

// The piece of each triangle, in [0, pieces). `pieces` is clamped to
// [1, triangles] (no piece is empty); deterministic for given input.
std::vector<int> surfacePieces(const Points3& vertices, const Triangles& triangles, int pieces);

// One piece's triangles and the vertices they use, both as indices into the
// whole surface in increasing order. Vertices no triangle uses go to piece
// 0, so the pieces together hold every vertex.
struct SurfacePiece {
  std::vector<Index> triangles;
  std::vector<Index> vertices;
};
// The pieces named by `pieceOfTriangle` (from surfacePieces): as many as
// its largest piece number + 1 (one for a surface without triangles).
std::vector<SurfacePiece> splitSurface(Index vertexCount, const Triangles& triangles,
                                       const std::vector<int>& pieceOfTriangle);

}  // namespace tetskin
