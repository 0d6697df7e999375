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
// "has slivers (smallest dihedral angle 0.248 deg, largest radius-edge
// ratio 61.9), which slow the solvers"; empty when the mesh has none.
std::string sliverProblem(const TetQuality& quality);

}  // namespace tetskin
