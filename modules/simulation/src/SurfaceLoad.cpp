// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/SurfaceLoad.h"

#include <Eigen/Geometry>
#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

namespace tetskin {
namespace {

Eigen::Vector3d corner(const Eigen::VectorXd& coordinates, int node) {
  return coordinates.segment<3>(3 * static_cast<Index>(node));
}

// The face's area along its outward normal.
Eigen::Vector3d areaVector(const SurfaceLoad& load, Index f, const Eigen::VectorXd& coordinates) {
  return triangleAreaVector(corner(coordinates, load.faces(f, 0)),
                            corner(coordinates, load.faces(f, 1)),
                            corner(coordinates, load.faces(f, 2)));
}

}  // namespace

std::optional<std::string> surfaceLoadProblem(const SurfaceLoad& load, Index nodeCount) {
  if (load.faces.rows() == 0) return "it has no face";
  for (Index f = 0; f < load.faces.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (load.faces(f, k) < 0 || load.faces(f, k) >= nodeCount)
        return "face " + std::to_string(f) + " names node " + std::to_string(load.faces(f, k)) +
               ", which the level (" + std::to_string(nodeCount) + " nodes) lacks";
    if (load.faces(f, 0) == load.faces(f, 1) || load.faces(f, 1) == load.faces(f, 2) ||
        load.faces(f, 0) == load.faces(f, 2))
      return "face " + std::to_string(f) + " names a node twice";
  }
  if (!std::isfinite(load.pressure))
    return "its pressure must be finite, got " + formatNumber(load.pressure);
  if (!load.traction.allFinite()) return "its traction must be finite";
  return std::nullopt;
}

void addSurfaceLoadForces(const SurfaceLoad& load, const Eigen::VectorXd& rest,
                          const Eigen::VectorXd& positions, double factor,
                          Eigen::VectorXd& forces) {
  // A third of each face's force to each corner: the consistent load of a
  // constant load on a linear triangle. Pressure: -p n A; traction: t A
  // at rest.
  const double pressure = factor * load.pressure;
  const Eigen::Vector3d traction = factor * load.traction;
  const bool pushes = pressure != 0, pulls = traction.squaredNorm() > 0;
  for (Index f = 0; f < load.faces.rows(); ++f) {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (pushes) force -= pressure * areaVector(load, f, positions);
    if (pulls) force += areaVector(load, f, rest).norm() * traction;
    for (int k = 0; k < 3; ++k) forces.segment<3>(3 * load.faces(f, k)) += force / 3;
  }
}

double surfaceLoadEnergy(const SurfaceLoad& load, const Eigen::VectorXd& rest,
                         const Eigen::VectorXd& positions, double factor) {
  // The cone of a face over the origin holds a . (b x c) / 6.
  const auto coneVolume = [&](Index f, const Eigen::VectorXd& at) {
    return corner(at, load.faces(f, 0))
               .dot(corner(at, load.faces(f, 1)).cross(corner(at, load.faces(f, 2)))) /
           6;
  };
  double energy = 0;
  for (Index f = 0; f < load.faces.rows(); ++f) {
    if (load.pressure != 0)
      energy += factor * load.pressure * (coneVolume(f, positions) - coneVolume(f, rest));
    if (load.traction.squaredNorm() > 0) {
      const Eigen::Vector3d force = factor * areaVector(load, f, rest).norm() * load.traction;
      for (int k = 0; k < 3; ++k) {
        const int node = load.faces(f, k);
        energy -= force.dot(corner(positions, node) - corner(rest, node)) / 3;
      }
    }
  }
  return energy;
}

double loadedArea(const SurfaceLoad& load, const Eigen::VectorXd& positions) {
  double area = 0;
  for (Index f = 0; f < load.faces.rows(); ++f) area += areaVector(load, f, positions).norm();
  return area;
}

}  // namespace tetskin
