// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/MeshQuality.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace tetskin {
namespace {

std::array<Eigen::Vector3d, 4> corners(const TetMesh& mesh, Index e) {
  std::array<Eigen::Vector3d, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = mesh.nodes.row(mesh.elements(e, k)).transpose();
  return p;
}

}  // namespace

std::array<double, 6> dihedralAnglesDeg(const TetMesh& mesh, Index e) {
  const auto p = corners(mesh, e);
  static constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                      {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> angles{};
  for (int i = 0; i < 6; ++i) {
    const auto& [a, b, c, d] = edges[i];
    const Eigen::Vector3d axis = (p[b] - p[a]).normalized();
    // Directions from the edge to the two other corners, perpendicular to it.
    Eigen::Vector3d u = p[c] - p[a], v = p[d] - p[a];
    u -= u.dot(axis) * axis;
    v -= v.dot(axis) * axis;
    const double cosine = std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0);
    angles[i] = std::acos(cosine) * 180.0 / std::numbers::pi;
  }
  return angles;
}

double radiusEdgeRatio(const TetMesh& mesh, Index e) {
  const auto p = corners(mesh, e);
  const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double denominator = 2.0 * a.dot(b.cross(c));
  const Eigen::Vector3d offset =
      (a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b)) /
      denominator;
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, (p[i] - p[j]).norm());
  return offset.norm() / shortest;
}

double relativeVolume(const TetMesh& mesh, Index e) {
  const auto p = corners(mesh, e);
  double squares = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) squares += (p[i] - p[j]).squaredNorm();
  const double rms = std::sqrt(squares / 6.0);
  if (!(rms > 0)) return 0;
  return elementVolume(mesh, e) * 6.0 * std::sqrt(2.0) / (rms * rms * rms);
}

TetQuality measureQuality(const TetMesh& mesh) {
  TetQuality q;
  if (mesh.elementCount() == 0) return q;
  q.minDihedralDeg = 180;
  q.minVolume = std::numeric_limits<double>::infinity();
  q.minRelativeVolume = std::numeric_limits<double>::infinity();
  double sumRatio = 0;
  for (Index e = 0; e < mesh.elementCount(); ++e) {
    for (double angle : dihedralAnglesDeg(mesh, e)) {
      q.minDihedralDeg = std::min(q.minDihedralDeg, angle);
      q.maxDihedralDeg = std::max(q.maxDihedralDeg, angle);
    }
    const double ratio = radiusEdgeRatio(mesh, e);
    q.maxRadiusEdge = std::max(q.maxRadiusEdge, ratio);
    sumRatio += ratio;
    const double volume = elementVolume(mesh, e);
    q.minVolume = std::min(q.minVolume, volume);
    q.minRelativeVolume = std::min(q.minRelativeVolume, relativeVolume(mesh, e));
    q.totalVolume += volume;
  }
  q.meanRadiusEdge = sumRatio / static_cast<double>(mesh.elementCount());
  return q;
}

std::string flatElementProblem(const TetQuality& quality) {
  if (!(quality.minRelativeVolume < kFlatRelativeVolume)) return {};
  char text[120];
  std::snprintf(text, sizeof text, "has a flat element (relative volume %.2g, at least %g asked)",
                quality.minRelativeVolume, kFlatRelativeVolume);
  return text;
}

std::string sliverProblem(const TetQuality& quality) {
  if (!(quality.minDihedralDeg < kSliverDihedralDeg)) return {};
  char text[160];
  std::snprintf(text, sizeof text,
                "has slivers (smallest dihedral angle %.3g deg, largest radius-edge ratio %.3g), "
                "which slow the solvers",
                quality.minDihedralDeg, quality.maxRadiusEdge);
  return text;
}

std::map<std::string, double> TetQuality::asMap() const {
  return {{"min_dihedral_deg", minDihedralDeg},
          {"max_dihedral_deg", maxDihedralDeg},
          {"max_radius_edge", maxRadiusEdge},
          {"mean_radius_edge", meanRadiusEdge},
          {"min_volume", minVolume},
          {"min_relative_volume", minRelativeVolume},
          {"total_volume", totalVolume}};
}

}  // namespace tetskin
