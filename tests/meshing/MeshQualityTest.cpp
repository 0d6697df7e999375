// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "Shapes.h"
#include "tetskin/meshing/MeshQuality.h"

namespace tetskin {
namespace {

TEST(MeshQuality, RegularTetrahedronKnownAnswers) {
  TetMesh m;
  m.nodes.resize(4, 3);
  m.nodes << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  m.elements.resize(1, 4);
  m.elements << 0, 1, 2, 3;
  if (elementVolume(m, 0) < 0) std::swap(m.elements(0, 2), m.elements(0, 3));
  const double expected = std::acos(1.0 / 3.0) * 180.0 / M_PI;  // 70.5288 degrees
  for (double angle : dihedralAnglesDeg(m, 0)) EXPECT_NEAR(angle, expected, 1e-9);
  EXPECT_NEAR(radiusEdgeRatio(m, 0), std::sqrt(6.0) / 4.0, 1e-12);  // 0.612
  const TetQuality q = measureQuality(m);
  EXPECT_NEAR(q.minDihedralDeg, expected, 1e-9);
  EXPECT_NEAR(q.totalVolume, 8.0 / 3.0, 1e-12);
}

TEST(MeshQuality, CornerTetrahedron) {
  const TetMesh m = test::unitTetrahedron();
  const auto angles = dihedralAnglesDeg(m, 0);
  // Edges at the origin meet at right angles; the others at acos(1/sqrt(3)).
  EXPECT_NEAR(angles[0], 90, 1e-9);
  EXPECT_NEAR(angles[1], 90, 1e-9);
  EXPECT_NEAR(angles[2], 90, 1e-9);
  EXPECT_NEAR(angles[3], std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  // Circumradius sqrt(3)/2 over shortest edge 1.
  EXPECT_NEAR(radiusEdgeRatio(m, 0), std::sqrt(3.0) / 2.0, 1e-12);
}

// A sliver: four points of a square lifted alternately by h, nearly flat.
// Its smallest dihedral angle is under 1 degree, and sliverProblem says so
// with the angle; the corner tetrahedron has none.
TEST(MeshQuality, SliversAreNamedWithTheirAngle) {
  TetMesh m;
  m.nodes.resize(4, 3);
  const double h = 0.005;
  m.nodes << 0, 0, 0, 1, 0, h, 1, 1, 0, 0, 1, h;
  m.elements.resize(1, 4);
  m.elements << 0, 1, 2, 3;
  if (elementVolume(m, 0) < 0) std::swap(m.elements(0, 2), m.elements(0, 3));
  const TetQuality q = measureQuality(m);
  ASSERT_LT(q.minDihedralDeg, kSliverDihedralDeg);
  const std::string problem = sliverProblem(q);
  char angle[32];
  std::snprintf(angle, sizeof angle, "%.3g deg", q.minDihedralDeg);
  EXPECT_EQ(problem.rfind("has slivers (smallest dihedral angle ", 0), 0u) << problem;
  EXPECT_NE(problem.find(angle), std::string::npos) << problem << " / " << angle;
  EXPECT_EQ(sliverProblem(measureQuality(test::unitTetrahedron())), "");
}

}  // namespace
}  // namespace tetskin
