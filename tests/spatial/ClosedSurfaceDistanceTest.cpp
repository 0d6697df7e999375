// SPDX-License-Identifier: AGPL-3.0-or-later
// The signed distance to a closed surface: known answers on a cube (faces,
// edges, corners, inside and out), the sign against a sphere's exact
// distance, a surface wound inward, bounded queries, and the refusal of
// open and inconsistently wound surfaces.
#include <gtest/gtest.h>

#include <random>
#include <regex>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/spatial/ClosedSurfaceDistance.h"

namespace tetskin {
namespace {

using test::box;
using test::sphere;

// Expects `action` to throw an Error whose message matches `pattern`.
template <typename Action>
void expectError(Action&& action, const std::string& pattern) {
  const std::string text = test::errorText(action);
  EXPECT_TRUE(std::regex_search(text, std::regex(pattern))) << text;
}

SurfacePoint closestOf(const ClosedSurfaceDistance& d, const Eigen::Vector3d& p) {
  const auto hit = d.closest(p);
  EXPECT_TRUE(hit.has_value());
  return *hit;
}

TEST(ClosedSurfaceDistance, KnowsTheCubesFacesEdgesAndCornersInsideAndOut) {
  const ClosedSurfaceDistance cube(box({0, 0, 0}, {1, 1, 1}), "cube");
  struct Case {
    Eigen::Vector3d p, point, normal;
    double distance;
  };
  const double r3 = std::sqrt(3.0), r2 = std::sqrt(2.0);
  for (const Case& c : {
           Case{{0.5, 0.5, 2}, {0.5, 0.5, 1}, {0, 0, 1}, 1},               // above a face
           Case{{0.5, 0.5, 0.4}, {0.5, 0.5, 0}, {0, 0, -1}, -0.4},         // inside, nearest z = 0
           Case{{2, 2, 2}, {1, 1, 1}, Eigen::Vector3d(1, 1, 1) / r3, r3},  // off a corner
           Case{{2, 0.5, 2}, {1, 0.5, 1}, Eigen::Vector3d(1, 0, 1) / r2, r2},  // off an edge
           Case{{0.9, 0.3, 0.5}, {1, 0.3, 0.5}, {1, 0, 0}, -0.1},         // inside, nearest x = 1
           Case{{1, 0.5, 0.5}, {1, 0.5, 0.5}, {1, 0, 0}, 0},              // on a face
           Case{{1, 1, 1}, {1, 1, 1}, Eigen::Vector3d(1, 1, 1) / r3, 0},  // on a corner
       }) {
    const SurfacePoint s = closestOf(cube, c.p);
    EXPECT_NEAR(s.distance, c.distance, 1e-12) << c.p.transpose();
    EXPECT_NEAR((s.point - c.point).norm(), 0, 1e-12) << c.p.transpose();
    EXPECT_NEAR((s.normal - c.normal).norm(), 0, 1e-12) << c.p.transpose();
  }
}

TEST(ClosedSurfaceDistance, TheSignAgreesWithASpheresExactDistance) {
  // The mesh lies within the sphere's chord error (1 - cos(pi/32)) r of
  // it; beyond that band the side must be the sphere's, and the distance
  // within the band of the exact one.
  const double radius = 1.0;
  const ClosedSurfaceDistance ball(sphere({0.2, -0.1, 0.3}, radius, 32, 48), "sphere");
  const double band = (1 - std::cos(3.14159265358979 / 32)) * radius * 1.01;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2, 2);
  int inside = 0, outside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    const double exact = (p - Eigen::Vector3d(0.2, -0.1, 0.3)).norm() - radius;
    const SurfacePoint s = closestOf(ball, p);
    EXPECT_NEAR(s.distance, exact, band) << p.transpose();
    if (std::abs(exact) > band) {
      EXPECT_EQ(s.distance < 0, exact < 0) << p.transpose();
      (exact < 0 ? inside : outside)++;
    }
    EXPECT_NEAR(s.normal.norm(), 1, 1e-12);
    EXPECT_NEAR((s.point + s.distance * s.normal - p).norm(), 0, 1e-9) << p.transpose();
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(ClosedSurfaceDistance, ASurfaceWoundInwardIsTurnedOutward) {
  SurfaceMesh inward = box({0, 0, 0}, {1, 1, 1});
  inward.triangles.col(1).swap(inward.triangles.col(2));
  const ClosedSurfaceDistance cube(inward, "inward cube");
  EXPECT_NEAR(closestOf(cube, {0.5, 0.5, 0.4}).distance, -0.4, 1e-12);
  EXPECT_NEAR(closestOf(cube, {0.5, 0.5, 3}).distance, 2, 1e-12);
}

TEST(ClosedSurfaceDistance, ABoundedQueryFindsNothingFartherThanItsRadius) {
  const ClosedSurfaceDistance cube(box({0, 0, 0}, {1, 1, 1}), "cube");
  EXPECT_FALSE(cube.closest({0.5, 0.5, 3}, 1.5).has_value());
  EXPECT_FALSE(cube.closest({0.5, 0.5, 0.5}, 0.4).has_value());  // deep inside
  ASSERT_TRUE(cube.closest({0.5, 0.5, 2.4}, 1.5).has_value());
  EXPECT_NEAR(cube.closest({0.5, 0.5, 2.4}, 1.5)->distance, 1.4, 1e-12);
}

TEST(ClosedSurfaceDistance, RefusesOpenAndInconsistentlyWoundSurfaces) {
  SurfaceMesh open = box({0, 0, 0}, {1, 1, 1});
  open.triangles.conservativeResize(open.triangleCount() - 1, 3);
  expectError([&] { ClosedSurfaceDistance(open, "lid.obj"); },
              "^lid.obj: the edge [0-9]+-[0-9]+ of triangle [0-9]+ is in 1 triangle; an "
              "obstacle must be a closed surface");
  SurfaceMesh flipped = box({0, 0, 0}, {1, 1, 1});
  std::swap(flipped.triangles(0, 1), flipped.triangles(0, 2));
  expectError([&] { ClosedSurfaceDistance(flipped, "flip.obj"); },
              "^flip.obj: the edge .* is run in the same direction by both its triangles");
  SurfaceMesh flat = box({0, 0, 0}, {1, 1, 1});
  flat.positions.col(2).setZero();
  expectError([&] { ClosedSurfaceDistance(flat, "flat.obj"); },
              "^flat.obj: triangle [0-9]+ has zero area");
}

}  // namespace
}  // namespace tetskin
