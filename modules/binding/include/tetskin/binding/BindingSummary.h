// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How good a binding is, in numbers a researcher can compare across methods
// and levels: printed by `tetskin bind`, shown by the GUI.

#include <string>
#include <vector>

#include "tetskin/core/SurfaceBinding.h"

namespace tetskin {

struct BindingSummary {
  Index vertices = 0;
  double shareInside = 0;  // share of vertices whose weights are all >= 0
  double diagonal = 0;     // reference length: the surface's bounding-box diagonal
  // |distance| / diagonal at the 50th, 90th, 99th percentile and the maximum.
  double distanceP50 = 0, distanceP90 = 0, distanceP99 = 0, distanceMax = 0;
  std::vector<Index> worstBarycentric;  // up to 5 vertices, most negative weight first
  std::vector<Index> worstDistance;     // up to 5 vertices, farthest first
};

BindingSummary summarizeBinding(const SurfaceBinding& binding, double diagonal);

// A few lines of plain text (used by the CLI).
std::string formatSummary(const BindingSummary& summary, const SurfaceBinding& binding);

}  // namespace tetskin
