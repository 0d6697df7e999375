// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Tetrahedralization of a closed, repaired surface by TetGen (the library) or
// Netgen (nglib). A part of the surface wound inward (SurfaceNesting.h: the
// inner sphere of a hollow ball, as repair winds it) bounds a cavity, which
// stays empty. Both return positively oriented tetrahedra and throw
// tetskin::Error when the mesher refuses the input. A mesher may also crash
// or hang on hostile input: run them through runIsolated (IsolatedJobs.h).

#include <string>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin {

// TetGen `-pq<radiusEdgeRatio>Q`: a constrained Delaunay mesh whose elements
// have a radius-edge ratio at most `radiusEdgeRatio` (the report's quality
// levels 2.0, 1.8, 1.6, 1.4, 1.2; closer to 1 means finer and better shaped).
// A positive `maxVolume` adds `-a<maxVolume>`, bounding every element's
// volume: how a shape whose surface needs few elements (a box) is meshed
// finer. TetGen keeps every input triangle, so no bound gives fewer elements
// than the unbounded mesh.
TetMesh tetrahedralizeWithTetGen(const SurfaceMesh& surface, double radiusEdgeRatio,
                                 double maxVolume = 0.0);

// Netgen's five fineness presets, as in its GUI.
enum class NetgenFineness { VeryCoarse = 0, Coarse = 1, Moderate = 2, Fine = 3, VeryFine = 4 };
const char* netgenFinenessName(NetgenFineness fineness);

// Whether this build has Netgen (CMake option TETSKIN_WITH_NETGEN).
bool netgenAvailable();

// Netgen lives in a module of its own (libtetskin_netgen.so; it brings MPI
// and Python), loaded when first used. This loads it now: before forking
// jobs that use it, so each does not load it again. Throws where it cannot
// be loaded.
void loadNetgen();

// Netgen from the surface as STL geometry (remeshes the surface, then the
// volume). A positive `maxEdge` replaces the preset's element size bound
// (Netgen's maxh, an edge length), so it gives coarser meshes as well as
// finer ones.
TetMesh tetrahedralizeWithNetgen(const SurfaceMesh& surface, NetgenFineness fineness,
                                 double maxEdge = 0.0);

}  // namespace tetskin
