// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

const Eigen::Vector3d A(0, 0, 0), B(1, 0, 0), C(0, 1, 0);

TEST(TriangleDistance, EveryRegion) {
  // Face
  auto r = closestPointOnTriangle({0.25, 0.25, 2}, A, B, C);
  EXPECT_NEAR(r.squaredDistance, 4, 1e-15);
  EXPECT_TRUE(r.barycentric.isApprox(Eigen::Vector3d(0.5, 0.25, 0.25)));
  // Vertices
  EXPECT_TRUE(closestPointOnTriangle({-1, -1, 0}, A, B, C).point.isApprox(A));
  EXPECT_TRUE(closestPointOnTriangle({2, -0.5, 0}, A, B, C).point.isApprox(B));
  EXPECT_TRUE(closestPointOnTriangle({-0.1, 3, 1}, A, B, C).point.isApprox(C));
  // Edges
  r = closestPointOnTriangle({0.5, -1, 0}, A, B, C);
  EXPECT_TRUE(r.point.isApprox(Eigen::Vector3d(0.5, 0, 0)));
  EXPECT_NEAR(r.squaredDistance, 1, 1e-15);
  r = closestPointOnTriangle({1, 1, 0}, A, B, C);
  EXPECT_TRUE(r.point.isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(r.barycentric.isApprox(Eigen::Vector3d(0, 0.5, 0.5)));
}

TEST(TriangleDistance, NoSampledPointIsCloser) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2), w(0, 1);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)),
        c(u(rng), u(rng), u(rng)), p(u(rng), u(rng), u(rng));
    const auto r = closestPointOnTriangle(p, a, b, c);
    EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-12);
    EXPECT_GE(r.barycentric.minCoeff(), -1e-12);
    EXPECT_TRUE(
        (r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c).isApprox(r.point));
    for (int s = 0; s < 200; ++s) {
      double x = w(rng), y = w(rng);
      if (x + y > 1) x = 1 - x, y = 1 - y;
      const Eigen::Vector3d q = a + x * (b - a) + y * (c - a);
      EXPECT_LE(r.squaredDistance, (p - q).squaredNorm() + 1e-12);
    }
  }
}

TEST(TriangleDistance, DegenerateTriangleFallsBackToEdges) {
  const auto r = closestPointOnTriangle({0.5, 1, 0}, A, B, Eigen::Vector3d(2, 0, 0));
  EXPECT_NEAR(r.squaredDistance, 1.0, 1e-15);
  EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-15);
}

TEST(TriangleDistance, PlaneBarycentricIsUnclamped) {
  const Eigen::Vector3d bc = planeBarycentric({2, 0, 5}, A, B, C);
  EXPECT_TRUE(bc.isApprox(Eigen::Vector3d(-1, 2, 0)));
}

// The feature a closest point lies on, from the exact zeros of its
// barycentric coordinates: above the face, beside the edge opposite a
// corner, and out past a corner.
TEST(TriangleDistance, TheClosestFeatureIsTheFaceAnEdgeOrACorner) {
  const Eigen::Vector3d centre = (A + B + C) / 3;
  const TriangleFeature face = closestFeature(
      closestPointOnTriangle(centre + Eigen::Vector3d(0, 0, 1), A, B, C).barycentric);
  EXPECT_EQ(face.kind, TriangleFeature::Face);
  const Eigen::Vector3d beyondBC = 0.5 * (B + C) + 2 * (0.5 * (B + C) - A);  // past edge B-C
  const TriangleFeature edge =
      closestFeature(closestPointOnTriangle(beyondBC, A, B, C).barycentric);
  EXPECT_EQ(edge.kind, TriangleFeature::Edge);
  EXPECT_EQ(edge.corner, 0);  // the edge opposite A
  const Eigen::Vector3d pastB = B + 3 * (B - centre);
  const TriangleFeature corner = closestFeature(closestPointOnTriangle(pastB, A, B, C).barycentric);
  EXPECT_EQ(corner.kind, TriangleFeature::Corner);
  EXPECT_EQ(corner.corner, 1);
}

}  // namespace
}  // namespace tetskin
