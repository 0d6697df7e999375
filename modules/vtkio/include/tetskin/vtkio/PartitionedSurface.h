// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A surface in pieces, as ParaView's parallel readers and writers keep it: a
// .pvtp naming one .vtp per piece (the .pvtp's name + "_pieceK.vtp", beside
// it), so that each rank of `mpiexec pvbatch` or `pvserver` reads only its
// own piece. Each piece holds its triangles and the points they use, with
// every point and cell array and the field data of the whole, plus the
// arrays GlobalPointIds and GlobalCellIds (VTK's global-id attributes): the
// index of each point and triangle in the whole surface. With them the
// pieces read back whole, point for point in the original order, and
// ParaView knows which points at piece borders are one.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <vector>

#include "tetskin/core/SurfacePieces.h"

class vtkPolyData;

namespace tetskin {

// Writes `whole` (points and polygons only) as the .pvtp `path` and its
// pieces (from splitSurface over whole's polygons, in order). An earlier
// .pvtp there is removed first, each piece is written atomically and the
// .pvtp last, so an interrupted write never leaves a .pvtp naming a
// missing, half-written or stale piece; pieces of an earlier write to
// `path` beyond this one's count are removed.
void writePvtp(const std::filesystem::path& path, vtkPolyData* whole,
               const std::vector<SurfacePiece>& pieces);

// The piece files a .pvtp names, as found from its folder. Throws Error
// naming the file when it is no .pvtp (a VTKFile of type PPolyData) or names
// no piece.
std::vector<std::filesystem::path> pvtpPieceFiles(const std::filesystem::path& path);

// The surface a .pvtp holds, whole: pieces with GlobalPointIds and
// GlobalCellIds (ours) are merged into the surface they were cut from, each
// point and triangle once, in their original order, without those two
// arrays; pieces without them (other writers') are appended, so that points
// at piece borders appear once per piece. Each piece is checked as readVtp
// checks a .vtp; errors name the piece's file.
vtkSmartPointer<vtkPolyData> readPvtp(const std::filesystem::path& path);

// The name of piece `piece` of the .pvtp `path` (without folder).
std::string pvtpPieceName(const std::filesystem::path& path, int piece);

}  // namespace tetskin
