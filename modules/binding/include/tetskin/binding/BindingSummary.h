// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How good a binding is, in numbers a researcher can compare across methods
// and levels: printed by `tetskin bind`, shown by the GUI.

#include <string>
#include <vector>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/TetMesh.h"

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

// Inputs: a binding of #V vertices; `diagonal`, the length distances are
// measured against (model units). Output: the summary above.
BindingSummary summarizeBinding(const SurfaceBinding& binding, double diagonal);

// The 90th percentile of the vertices' distance from the control mesh's
// boundary, over the control mesh's bounding-box diagonal, above which
// misfitWarning speaks. (The bundled bunny bound to its coarsest level, 598
// elements, has 1.1e-2; a coarse cage around a detailed model may have a
// few hundredths; a surface moved off its dataset, or one of another
// object, has tenths.)
constexpr double kMisfitDistance = 0.1;

// Why the binding may not be what was meant, when a tenth of the vertices
// lie farther than kMisfitDistance of `controlDiagonal` from the boundary of
// the control mesh named `control` ("a tenth of the vertices lie more than
// 95% of level 2's diagonal from its boundary: ..."); empty otherwise.
std::string misfitWarning(const BindingSummary& summary, double controlDiagonal,
                          const std::string& control);
// The same for a binding to `level` of `mesh`, named "level N".
std::string misfitWarning(const BindingSummary& summary, const MultiLevelTetMesh& mesh, int level);

// A few lines of plain text (used by the CLI).
std::string formatSummary(const BindingSummary& summary, const SurfaceBinding& binding);

}  // namespace tetskin
