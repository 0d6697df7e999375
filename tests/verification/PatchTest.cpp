// SPDX-License-Identifier: AGPL-3.0-or-later
// The patch test: an affine deformation x = F X + b imposed on the boundary
// of an irregular mesh is reproduced exactly inside by the static solve
// (to 1e-10 of the body's size), with the same stress in every element.
// Linear tetrahedra with the corotated material pass it for any F with
// positive determinant, rotation included: every element then has the same
// deformation gradient, hence the same rotation and stress, whose forces
// cancel at every inner node.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <vector>

#include "Shapes.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::test {
namespace {

// A unit cube of 4 x 4 x 4 cells, its inner nodes moved off the grid by up
// to 0.15 of a cell (deterministically), so that no element is like another.
TetMesh irregularCube(std::vector<int>& boundary) {
  TetMesh mesh = tetGrid(4, 4, 4, {1, 1, 1});
  boundary.clear();
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    const Eigen::RowVector3d p = mesh.nodes.row(v);
    const bool onFace = (p.array() < 1e-9).any() || (p.array() > 1 - 1e-9).any();
    if (onFace) {
      boundary.push_back(static_cast<int>(v));
      continue;
    }
    const double k = static_cast<double>(v);
    mesh.nodes.row(v) +=
        0.25 * 0.15 *
        Eigen::RowVector3d(std::sin(1.7 * k), std::cos(2.3 * k), std::sin(0.7 * k + 1));
  }
  return mesh;
}

TEST(PatchTest, AnAffineDeformationOnTheBoundaryIsReproducedInside) {
  std::vector<int> boundary;
  const TetMesh cube = irregularCube(boundary);
  for (Index e = 0; e < cube.elementCount(); ++e) ASSERT_GT(elementVolume(cube, e), 0);
  // A stretch with shear, turned by 30 degrees: large rotation, small strain.
  Eigen::Matrix3d stretch;
  stretch << 1.02, 0.01, 0.0, 0.01, 0.99, 0.015, 0.0, 0.015, 1.01;
  const Eigen::Matrix3d F =
      Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
      stretch;
  const Eigen::RowVector3d b(0.3, -0.2, 0.1);
  const auto affine = [&](const Eigen::RowVector3d& X) -> Eigen::RowVector3d {
    return (F * X.transpose()).transpose() + b;
  };

  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 1e6;
  options.material.poissonRatio = 0.3;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-12;
  MultiLevelTetMesh dataset;
  appendLevel(dataset, cube);
  Simulation sim(dataset, 0, options);
  sim.setFixedNodes(boundary);
  Points3 targets(static_cast<Index>(boundary.size()), 3);
  for (std::size_t k = 0; k < boundary.size(); ++k)
    targets.row(static_cast<Index>(k)) = affine(cube.nodes.row(boundary[k]));
  sim.setKinematicTargets(boundary, targets);

  const StaticStats stats = sim.solveStatic(1e-13);
  EXPECT_TRUE(stats.converged) << stats.residual;
  const SimulationState state = sim.state();
  double error = 0;
  for (Index v = 0; v < cube.nodeCount(); ++v)
    error = std::max(error, (state.positions.row(v) - affine(cube.nodes.row(v))).norm());
  std::printf("patch test: largest distance from the affine map %.3g (%d Newton iterations)\n",
              error, stats.iterations);
  EXPECT_LT(error, 1e-10);
  // The same stress in every element.
  const Eigen::VectorXd stress = sim.frameFields(state).vonMisesStress;
  EXPECT_GT(stress.minCoeff(), 0);
  EXPECT_LT(stress.maxCoeff() - stress.minCoeff(), 1e-8 * stress.maxCoeff());
}

}  // namespace
}  // namespace tetskin::test
