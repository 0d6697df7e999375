// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "Shapes.h"
#include "tetskin/spatial/TetLocator.h"

namespace tetskin {
namespace {

TEST(TetLocator, InsidePointsGetTheirElementAndReproduceThemselves) {
  const TetMesh grid = test::tetGrid(3, 3, 3, {3, 3, 3});
  const TetLocator locator(grid);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> inside(0.01, 2.99), outside(-2, 5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p(inside(rng), inside(rng), inside(rng));
    const TetLocation at = locator.locate(p);
    ASSERT_GE(at.element, 0);
    EXPECT_EQ(at.squaredDistance, 0.0);
    EXPECT_GE(at.barycentric.minCoeff(), -1e-12);
    EXPECT_NEAR(at.barycentric.sum(), 1.0, 1e-12);
    Eigen::Vector3d back = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      back += at.barycentric[k] * grid.nodes.row(grid.elements(at.element, k)).transpose();
    EXPECT_LT((back - p).norm(), 1e-12);
  }
  // Outside: the nearest element, weights extrapolated but still exact.
  const Eigen::Vector3d far(4.5, -1.0, 1.5);
  const TetLocation at = locator.locate(far);
  EXPECT_NEAR(at.squaredDistance, 1.5 * 1.5 + 1.0, 1e-12);  // to the edge x = 3, y = 0
  EXPECT_LT(at.barycentric.minCoeff(), 0.0);
  Eigen::Vector3d back = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
    back += at.barycentric[k] * grid.nodes.row(grid.elements(at.element, k)).transpose();
  EXPECT_LT((back - far).norm(), 1e-9);
}

}  // namespace
}  // namespace tetskin
