// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Shape statistics of a tetrahedral mesh, reported per candidate and per level.

#include <array>
#include <map>
#include <string>

#include "tetskin/core/TetMesh.h"

namespace tetskin {

struct TetQuality {
  double minDihedralDeg = 0;  // smallest interior dihedral angle
  double maxDihedralDeg = 0;  // largest
  double maxRadiusEdge = 0;   // circumradius / shortest edge, worst element (>= 0.612)
  double meanRadiusEdge = 0;
  double minVolume = 0;
  double totalVolume = 0;
  // The flattest element's volume over that of the regular tetrahedron
  // with its root-mean-square edge (1 for the regular one, 0 for flat).
  double minRelativeVolume = 0;

  // Named values for the dataset config (level "statistics").
  std::map<std::string, double> asMap() const;
};

// The six interior dihedral angles of element e, in degrees.
std::array<double, 6> dihedralAnglesDeg(const TetMesh& mesh, Index e);
// Circumradius over shortest edge of element e (0.612 for the regular tet).
double radiusEdgeRatio(const TetMesh& mesh, Index e);

TetQuality measureQuality(const TetMesh& mesh);

// Below this smallest dihedral angle a mesh's worst elements are slivers:
// nearly flat, they make its system ill-conditioned. (A TetGen level of a
// decimated cylinder, 0.25 deg at worst: 75.7 CG iterations a step under
// sag, against 32.4 on Netgen's level of about the same size, 3889 and
// 3171 elements, 20 deg.)
constexpr double kSliverDihedralDeg = 1.0;
// An element flatter than this (relative volume, see TetQuality) is flat:
// a written level has none (build rejects such a candidate as a failed
// run). A sliver of four corners of a square lifted apart has relative
// volume 0.018 at a smallest dihedral angle of 1.15 degrees, 0.0018 at
// 0.115 and 1.8e-4 at 0.0115: the bound catches elements flat in all but
// rounding. (TetGen's levels of a decimated cylinder,
// tests/data/decimated_cylinder.obj, reach 5.6e-4 at every quality, with
// its -q/D minimum dihedral angle at 5 or 10 degrees as well: such slivers
// stay a warning, sliverProblem, with Netgen as the way out.)
constexpr double kFlatRelativeVolume = 1e-4;
// Volume of element e over that of the regular tetrahedron with its RMS edge.
double relativeVolume(const TetMesh& mesh, Index e);
// "has a flat element (relative volume 2e-05, at most 0.001)"; empty when none.
std::string flatElementProblem(const TetQuality& quality);

// "has slivers (smallest dihedral angle 0.248 deg, largest radius-edge
// ratio 61.9), which slow the solvers"; empty when the mesh has none.
std::string sliverProblem(const TetQuality& quality);

}  // namespace tetskin
