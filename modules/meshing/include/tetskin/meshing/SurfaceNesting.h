// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How the closed parts of a surface lie inside one another, and which
// regions they enclose hold material. Read by the nonzero winding rule, as
// the parts are wound: a point is material where the winding numbers of the
// parts around it do not add up to 0. So a hollow ball is an outer sphere
// wound outward and an inner one wound inward (facing into the cavity, as
// STL files have it): 1 - 1 = 0 inside the inner one, a cavity. An inner
// sphere wound outward (2 inside it) is solid through, as are two
// overlapping parts (2 where they overlap).

#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// The parts of a surface: triangles connected across edges that exactly two
// triangles share (an edge of three or more triangles, or a vertex where
// parts touch, joins nothing).
struct SurfaceParts {
  // The triangles of each part, parts in order of their first triangle,
  // each part's in breadth-first order from its first.
  std::vector<std::vector<int>> triangles;
  // Per triangle of the mesh: the earlier triangle of its part it was
  // reached from, across a shared edge (-1 for a part's first).
  std::vector<int> reachedFrom;
};
SurfaceParts surfaceParts(const SurfaceMesh& mesh);

// The signed volume the triangles `part` of `mesh` enclose: positive wound
// outward, negative wound inward.
double partVolume(const SurfaceMesh& mesh, const std::vector<int>& part);

// For each of `parts` (closed, not intersecting one another), the others
// that enclose it.
std::vector<std::vector<int>> enclosingParts(const SurfaceMesh& mesh,
                                             const std::vector<std::vector<int>>& parts);

// Whether each of `parts` bounds a cavity: just inside it (inside it and
// the parts enclosing it, `enclosing` from enclosingParts), their winding
// numbers, +1 for one wound outward and -1 for one wound inward, add up to 0.
std::vector<char> cavityParts(const SurfaceMesh& mesh, const std::vector<std::vector<int>>& parts,
                              const std::vector<std::vector<int>>& enclosing);

// The generalized winding number of the triangles `part` of `mesh` about
// `point`: +1 inside a closed part wound outward, -1 inside one wound
// inward, 0 outside (Jacobson et al. 2013: the solid angles' sum over 4 pi);
// on the part itself it jumps (the solid angle formula's sign there).
double windingNumber(const SurfaceMesh& mesh, const std::vector<int>& part,
                     const Eigen::Vector3d& point);

// One point inside each cavity (cavityParts), off every triangle: what
// TetGen is given as a hole, so it leaves the cavity empty.
std::vector<Eigen::Vector3d> cavityPoints(const SurfaceMesh& mesh);

}  // namespace tetskin
