// SPDX-License-Identifier: AGPL-3.0-or-later
// Cook's membrane (Cook 1974): a tapered panel, corners (0, 0), (48, 44),
// (48, 60), (0, 44), clamped on its edge x = 0 and sheared by a uniform
// vertical traction on its edge x = 48 (1 N in all), E = 1, nu = 1/3,
// plane stress. The reference is the vertical displacement of the loaded
// edge's mid-point (48, 52) on converged meshes, 23.96, the value codes
// are measured on (the corner (48, 60) moves further). Here the panel is a
// slab 1 thick, one layer of tetrahedra through it, its faces free (plane
// stress), E = 1e3 so that the corotated body stays in the linear range
// (the mid-point turns by 5e-4), the displacement read times E. Linear
// tetrahedra (constant strain) lock in its bending and converge from
// below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "BoundarySelection.h"
#include "Shapes.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin::test {
namespace {

constexpr double kYoungs = 1e3;
constexpr double kReference = 23.96;
constexpr double kThickness = 1;  // times F / E, F = 1 N

// The panel meshed by k x k cells in its plane: a unit grid mapped
// bilinearly onto the trapezoid (orientation kept: its corners in the
// grid's order), z the thickness.
TetMesh panel(int k) {
  TetMesh mesh = tetGrid(k, k, 1, {1, 1, kThickness});
  const Eigen::Vector2d A(0, 0), B(48, 44), C(48, 60), D(0, 44);
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    const double u = mesh.nodes(v, 0), w = mesh.nodes(v, 1);
    const Eigen::Vector2d p = (1 - u) * (1 - w) * A + u * (1 - w) * B + u * w * C + (1 - u) * w * D;
    mesh.nodes(v, 0) = p.x();
    mesh.nodes(v, 1) = p.y();
  }
  return mesh;
}

// The loaded edge's mid-point's vertical displacement (the mean of its two
// nodes, z = 0 and the thickness) times E t / F: k even.
double midEdgeDisplacement(int k) {
  const TetMesh mesh = panel(k);
  MultiLevelTetMesh dataset;
  appendLevel(dataset, mesh);
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = kYoungs;
  options.material.poissonRatio = 1.0 / 3.0;
  options.material.density = 1;
  options.solver = SolverKind::Multigrid;
  options.tolerance = 1e-10;
  Simulation sim(dataset, 0, options);
  std::vector<int> clamped, middle;
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    if (mesh.nodes(v, 0) < 1e-9) clamped.push_back(static_cast<int>(v));
    if (mesh.nodes(v, 0) > 48 - 1e-9 && std::abs(mesh.nodes(v, 1) - 52) < 1e-9)
      middle.push_back(static_cast<int>(v));
  }
  sim.setFixedNodes(clamped);
  // The sheared edge's faces: 16 x 1, so 1/16 Pa is 1 N.
  SurfaceLoad shear;
  shear.faces = boundaryFacesWhere(mesh, [&](Index v) { return mesh.nodes(v, 0) > 48 - 1e-9; });
  shear.traction = {0, 1.0 / (16 * kThickness), 0};
  sim.setSurfaceLoads({shear});
  const StaticStats stats = sim.solveStatic();
  EXPECT_TRUE(stats.converged) << "k = " << k << ": residual " << stats.residual << " of "
                               << stats.load;
  const Points3 x = sim.state().positions;
  double v = 0;
  EXPECT_EQ(middle.size(), 2u);
  for (int node : middle) v += x(node, 1) - mesh.nodes(node, 1);
  return v / static_cast<double>(middle.size()) * kYoungs * kThickness;
}

std::vector<double> refined(const std::vector<int>& cells) {
  std::vector<double> middles;
  for (int k : cells) {
    middles.push_back(midEdgeDisplacement(k));
    std::printf(
        "Cook's membrane, %2d x %2d cells (%5d tetrahedra): v(48, 52) %.5g, reference %.4g, "
        "error %+.3g%%\n",
        k, k, 6 * k * k, middles.back(), kReference, 100 * (middles.back() / kReference - 1));
  }
  for (std::size_t i = 0; i + 1 < middles.size(); ++i)
    std::printf("order from %d to %d cells: %.3f against the reference\n", cells[i], cells[i + 1],
                std::log2((kReference - middles[i]) / (kReference - middles[i + 1])));
  return middles;
}

TEST(CooksMembrane, TheLoadedEdgeConvergesToTheReferenceFromBelow) {
  const std::vector<double> middles = refined({4, 8, 16, 32});
  for (std::size_t i = 0; i + 1 < middles.size(); ++i) {
    EXPECT_LT(middles[i], middles[i + 1]);
    EXPECT_LT(middles[i + 1], kReference);
  }
  const double order = std::log2((kReference - middles[2]) / (kReference - middles[3]));
  EXPECT_GT(order, 1.4);  // 16 to 32 cells
  EXPECT_LT(order, 2.5);
  EXPECT_NEAR(middles.back(), kReference, 0.04 * kReference);
}

// The finer meshes, for the script (tests/verification/verification_large.sh).
TEST(CooksMembrane, DISABLED_TheLoadedEdgeOnFinerMeshes) {
  refined({16, 32, 64});
}

}  // namespace
}  // namespace tetskin::test
