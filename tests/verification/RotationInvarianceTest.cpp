// SPDX-License-Identifier: AGPL-3.0-or-later
// Rotation invariance, the property that separates corotated from linear
// FEM: the rest shape turned by 90 degrees (and moved) has no elastic force
// (to 1e-12 of the body's force scale E h^2), where linear FEM's forces,
// K (x - X), are of the order of that scale.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <vector>

#include "Shapes.h"
#include "tetskin/simulation/CorotatedFem.h"

namespace tetskin::test {
namespace {

TEST(RotationInvariance, ARotatedRestShapeHasNoElasticForce) {
  const TetMesh bar = tetGrid(8, 2, 2, {4, 1, 1});
  ElasticMaterial material;
  material.youngsModulus = 1e6;
  material.poissonRatio = 0.3;
  CorotatedFem fem(bar, material);
  const Eigen::VectorXd& rest = fem.restPositions();
  const double h = 0.5;  // the cells' size
  const double scale = material.youngsModulus * h * h;
  const std::vector<Eigen::Vector3d> axes = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                             Eigen::Vector3d(1, 1, 1).normalized()};
  for (const Eigen::Vector3d& axis : axes) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, axis).toRotationMatrix();
    Eigen::VectorXd x(rest.size());
    for (Index v = 0; v < fem.nodeCount(); ++v)
      x.segment<3>(3 * v) = R * rest.segment<3>(3 * v) + Eigen::Vector3d(2, -1, 0.5);
    const Eigen::VectorXd corotated = fem.dampedElasticForce(x, Eigen::VectorXd::Zero(x.size()), 0);
    // Linear FEM: the rest stiffness times the displacement.
    SparseMatrix K = fem.pattern();
    Eigen::VectorXd force;
    fem.update(rest, force, K);
    const Eigen::VectorXd linear = -(K * (x - rest));
    std::printf(
        "turned 90 degrees: largest force, corotated %.3g N, linear %.3g N (scale %.3g N)\n",
        corotated.cwiseAbs().maxCoeff(), linear.cwiseAbs().maxCoeff(), scale);
    EXPECT_LT(corotated.cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_GT(linear.cwiseAbs().maxCoeff(), 0.1 * scale);
  }
}

}  // namespace
}  // namespace tetskin::test
