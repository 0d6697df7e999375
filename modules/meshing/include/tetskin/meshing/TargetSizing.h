// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Element size bounds aimed at an element-count target (`build
// --size-to-targets`), for shapes whose quality levels alone give too few
// elements (a box meshes into 6 at every quality).
//
// Model: under a volume bound a, a mesh of a body of volume V has about
//   n(a) = n0 + k V / a
// elements, where n0 is the count without a bound (TetGen keeps every input
// triangle, so it cannot go below that; Netgen remeshes the surface, n0 = 0)
// and k > 1 because refinement leaves most elements well under the bound.
// The first bound guesses k; each next one measures k on the mesh before.

#include "tetskin/core/Types.h"

namespace tetskin {

// k for the first bound. TetGen bounds the volume from above and refines
// well below it: its meshes of a unit box under the bound that k = 2 gives
// had k = 2.2-3.4 at 600 to 12000 elements (the larger on small meshes and
// at q1.2). Netgen takes its bound, as an edge, for the size it aims at:
// its meshes of a 10 x 1 x 1 beam had k = 0.4-0.5.
constexpr double kFirstTetGenSizingFactor = 2.5;
constexpr double kFirstNetgenSizingFactor = 0.5;

// A candidate within this fraction of its target needs no further bound.
constexpr double kSizingTolerance = 0.1;

// Meshing rounds at most: the first guess and two corrections.
constexpr int kSizingRounds = 3;

// The first volume bound for `target` elements, with k = `factor`. Throws
// Error unless volume > 0, 0 <= unboundedElements < target and factor > 0.
double firstVolumeBound(double volume, double unboundedElements, double target, double factor);

// The next bound, after a mesh under `bound` got `elements` elements: the
// model's bound with k measured on that mesh, kept within a factor
// kMaxBoundStep of `bound` so that one odd mesh cannot send the next one
// to a runaway size.
constexpr double kMaxBoundStep = 8.0;
double nextVolumeBound(double volume, double unboundedElements, double target, double bound,
                       double elements);

// Netgen bounds an edge length (maxh), not a volume: the edge of the regular
// tetrahedron of volume `volumeBound`.
double edgeForVolumeBound(double volumeBound);

// Whether `elements` is within kSizingTolerance of `target`.
bool closeToTarget(double elements, double target);

}  // namespace tetskin
