// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/spatial/SurfaceDistance.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

// Every triangle tried: what the tree must agree with.
double bruteForceDistance(const Eigen::Vector3d& p, const SurfaceMesh& s) {
  double best = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < s.triangleCount(); ++t)
    best = std::min(best, closestPointOnTriangle(p, s.positions.row(s.triangles(t, 0)).transpose(),
                                                 s.positions.row(s.triangles(t, 1)).transpose(),
                                                 s.positions.row(s.triangles(t, 2)).transpose())
                              .squaredDistance);
  return std::sqrt(best);
}

TEST(SurfaceDistance, KnownDistancesToABox) {
  const SurfaceMesh box = test::box({0, 0, 0}, {1, 1, 1});
  Points3 points(4, 3);
  points << 0.5, 0.5, 0.5,  // the centre: half an edge from every face
      2, 0.5, 0.5,          // one unit off a face
      2, 2, 0.5,            // off an edge: sqrt(2)
      0.25, 0, 0.5;         // on a face
  const std::vector<double> d = distancesToSurface(points, box);
  EXPECT_NEAR(d[0], 0.5, 1e-15);
  EXPECT_NEAR(d[1], 1.0, 1e-15);
  EXPECT_NEAR(d[2], std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(d[3], 0.0, 1e-15);
}

TEST(SurfaceDistance, AgreesWithBruteForceOnRandomPoints) {
  const SurfaceMesh surface =
      test::merge(test::box({0, 0, 0}, {1, 2, 1}), test::box({0.5, 0.5, 0.5}, {3, 1, 2}));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2, 4);
  Points3 points(500, 3);
  for (Index i = 0; i < points.rows(); ++i)
    points.row(i) << coordinate(random), coordinate(random), coordinate(random);
  const std::vector<double> d = distancesToSurface(points, surface);
  for (Index i = 0; i < points.rows(); ++i)
    EXPECT_NEAR(d[static_cast<std::size_t>(i)],
                bruteForceDistance(points.row(i).transpose(), surface), 1e-12)
        << "point " << i;
}

TEST(SurfaceDistance, OneSidedDistanceIsTheAreaWeightedMeanAndTheLargest) {
  // A unit square (two triangles) lifted 1 above the box's top, and the box.
  SurfaceMesh lid;
  lid.positions.resize(4, 3);
  lid.positions << 0, 2, 0, 1, 2, 0, 1, 2, 1, 0, 2, 1;
  lid.triangles.resize(2, 3);
  lid.triangles << 0, 2, 1, 0, 3, 2;
  const SurfaceMesh box = test::box({0, 0, 0}, {1, 1, 1});
  const OneSidedDistance lidToBox = oneSidedDistance(lid, box);
  EXPECT_NEAR(lidToBox.max, 1.0, 1e-15);
  EXPECT_NEAR(lidToBox.mean, 1.0, 1e-15);
  // From the box to the lid: the top corners 1 away, the bottom ones 2.
  const OneSidedDistance boxToLid = oneSidedDistance(box, lid);
  EXPECT_NEAR(boxToLid.max, 2.0, 1e-15);
  EXPECT_GE(boxToLid.farthestVertex, 0);
  EXPECT_NEAR(box.positions(boxToLid.farthestVertex, 1), 0.0, 0.0);
  // The weighted mean by hand: each vertex's third of its triangles' areas.
  const std::vector<double> w = vertexAreaWeights(box);
  const std::vector<double> d = distancesToSurface(box.positions, lid);
  double sum = 0, total = 0;
  for (std::size_t v = 0; v < w.size(); ++v) {
    sum += w[v] * d[v];
    total += w[v];
  }
  EXPECT_NEAR(total, 6.0, 1e-12);  // the box's area
  EXPECT_NEAR(boxToLid.mean, sum / total, 1e-15);
}

TEST(SurfaceDistance, ASurfaceWithoutTrianglesIsAnError) {
  EXPECT_THROW(distancesToSurface(Points3::Zero(1, 3), SurfaceMesh{}), Error);
}

}  // namespace
}  // namespace tetskin
