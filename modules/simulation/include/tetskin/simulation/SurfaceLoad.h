// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Loads spread over boundary faces of the control mesh, as FE packages
// apply them: a pressure, which pushes along each face's inward normal and
// follows the deformed surface, and a traction, a fixed force per area of
// the face at rest (a dead load). On a linear triangle a load constant over
// the face is carried to its corners by the consistent load, a third of
// its total to each.

#include <optional>
#include <string>

#include "tetskin/core/Types.h"

namespace tetskin {

struct SurfaceLoad {
  // Faces of the level (node ids), wound counter-clockwise seen from
  // outside the body (the winding says where "inward" is).
  Triangles faces;
  double pressure = 0;                                 // Pa: positive pushes into the body
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();  // Pa (N/m^2 of rest area)
};

// What is wrong with `load` on a level of `nodeCount` nodes: a face naming
// a node the level lacks, a face whose corners are not three different
// nodes, a pressure or traction not finite, or no face; nullopt when
// nothing is.
std::optional<std::string> surfaceLoadProblem(const SurfaceLoad& load, Index nodeCount);

// Inputs:
//   load       its faces' node ids index `rest` and `positions`
//   rest       3n coordinates at rest (the traction's areas)
//   positions  3n coordinates now (the pressure's areas and normals)
//   factor     scales the load (a load curve's factor)
// Output: the consistent nodal forces (N) added to `forces` (3n).
void addSurfaceLoadForces(const SurfaceLoad& load, const Eigen::VectorXd& rest,
                          const Eigen::VectorXd& positions, double factor, Eigen::VectorXd& forces);

// The potential energy (J) of `load` at `positions`, from the rest shape:
// the traction's -f . (x - X); the pressure's p (V(x) - V(X)), V the
// volume its faces enclose with the origin (the body's volume when the
// faces close it). Its gradient is minus the forces above for a traction,
// and for a pressure on a closed surface or on a patch whose rim stays
// put; a pressure on a moving open patch is not conservative.
double surfaceLoadEnergy(const SurfaceLoad& load, const Eigen::VectorXd& rest,
                         const Eigen::VectorXd& positions, double factor);

// The area (model units squared) of the load's faces at `positions`.
double loadedArea(const SurfaceLoad& load, const Eigen::VectorXd& positions);

}  // namespace tetskin
