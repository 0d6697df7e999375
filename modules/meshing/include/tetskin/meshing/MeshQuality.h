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

}  // namespace tetskin
