// SPDX-License-Identifier: AGPL-3.0-or-later
// NAFEMS LE10, the thick plate under pressure (NAFEMS R0015, 1990): a
// plate 0.6 m thick between the ellipses (x/2)^2 + y^2 = 1 and (x/3.25)^2
// + (y/2.75)^2 = 1, a quarter of it by symmetry, E = 210e3 MPa, nu = 0.3,
// a pressure of 1 MPa on its upper face z = 0.6; held along y on y = 0 and
// along x on x = 0 (the symmetry planes), along x and y on the outer
// ellipse, and along z on that face's mid-plane line z = 0.3 (rollers:
// Simulation::setHeldAxes). The reference is sigma_yy at D = (2, 0, 0.6),
// the inner hole's edge on the loaded face: -5.38 MPa. Units: m and MPa.
// Linear tetrahedra hold one stress per element; D's is read as the mean
// of its elements' stresses, weighted by their volume (the nodal average
// that post-processors show), on meshes structured in the ellipses' own
// coordinates.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "BoundarySelection.h"
#include "Shapes.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin::test {
namespace {

constexpr double kReference = -5.38;  // MPa

struct Plate {
  TetMesh mesh;
  Points3 grid;  // each node's (s, theta share, z share) in [0, 1]^3
};

// k: 2k cells across the ring, 6k around the quarter, 2k through the
// thickness (144 k^3 tetrahedra).
Plate plate(int k) {
  Plate p;
  p.mesh = tetGrid(2 * k, 6 * k, 2 * k, {1, 1, 1});
  p.grid = p.mesh.nodes;
  for (Index v = 0; v < p.mesh.nodeCount(); ++v) {
    const double s = p.grid(v, 0), theta = p.grid(v, 1) * M_PI / 2;
    p.mesh.nodes(v, 0) = ((1 - s) * 2 + s * 3.25) * std::cos(theta);
    p.mesh.nodes(v, 1) = ((1 - s) * 1 + s * 2.75) * std::sin(theta);
    p.mesh.nodes(v, 2) = 0.6 * p.grid(v, 2);
  }
  return p;
}

// sigma_yy at D: the volume-weighted mean over D's elements (and the
// largest of them in magnitude, printed).
double stressAtD(int k) {
  const Plate p = plate(k);
  const TetMesh& mesh = p.mesh;
  MultiLevelTetMesh dataset;
  appendLevel(dataset, mesh);
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 210e3;
  options.material.poissonRatio = 0.3;
  options.material.density = 1;
  options.solver = SolverKind::ConjugateGradient;
  options.tolerance = 1e-10;
  options.maxIterations = 20000;
  Simulation sim(dataset, 0, options);
  const auto at = [](double value, double where) { return std::abs(value - where) < 1e-9; };
  std::vector<int> held;
  std::vector<std::array<bool, 3>> axes;
  int d = -1;
  for (Index v = 0; v < mesh.nodeCount(); ++v) {
    const double s = p.grid(v, 0), t = p.grid(v, 1), z = p.grid(v, 2);
    std::array<bool, 3> axis{false, false, false};
    if (at(t, 0)) axis[1] = true;                // y = 0
    if (at(t, 1)) axis[0] = true;                // x = 0
    if (at(s, 1)) axis[0] = axis[1] = true;      // the outer ellipse
    if (at(s, 1) && at(z, 0.5)) axis[2] = true;  // its mid-plane line
    if (axis[0] || axis[1] || axis[2]) {
      held.push_back(static_cast<int>(v));
      axes.push_back(axis);
    }
    if (at(s, 0) && at(t, 0) && at(z, 1)) d = static_cast<int>(v);
  }
  EXPECT_GE(d, 0);
  sim.setHeldAxes(held, axes);
  SurfaceLoad pressure;
  pressure.faces = boundaryFacesWhere(mesh, [&](Index v) { return at(p.grid(v, 2), 1); });
  pressure.pressure = 1;
  sim.setSurfaceLoads({pressure});
  const StaticStats stats = sim.solveStatic();
  EXPECT_TRUE(stats.converged) << "k = " << k << ": residual " << stats.residual << " of "
                               << stats.load;
  const FrameFields fields = sim.frameFields(sim.state());
  double weighted = 0, volume = 0, extreme = 0;
  for (Index e = 0; e < mesh.elementCount(); ++e)
    for (int c = 0; c < 4; ++c)
      if (mesh.elements(e, c) == d) {
        const double v = elementVolume(mesh, e);
        weighted += v * fields.stress(e, 1);
        volume += v;
        if (std::abs(fields.stress(e, 1)) > std::abs(extreme)) extreme = fields.stress(e, 1);
      }
  const double mean = weighted / volume;
  std::printf(
      "NAFEMS LE10, k = %d (%6d tetrahedra): sigma_yy at D %.4g MPa (its elements' "
      "mean; the largest %.4g), reference %.3g, error %+.3g%%\n",
      k, static_cast<int>(mesh.elementCount()), mean, extreme, kReference,
      100 * (mean / kReference - 1));
  return mean;
}

TEST(NafemsLe10, TheStressAtDConvergesToTheReference) {
  std::vector<double> stresses;
  for (int k : {1, 2, 4}) stresses.push_back(stressAtD(k));
  for (std::size_t i = 0; i + 1 < stresses.size(); ++i)
    EXPECT_LT(std::abs(stresses[i + 1] - kReference), std::abs(stresses[i] - kReference));
  EXPECT_NEAR(stresses.back(), kReference, 0.25 * std::abs(kReference));
}

// The finer mesh, for the script (tests/verification/verification_large.sh).
TEST(NafemsLe10, DISABLED_TheStressAtDOnAFinerMesh) {
  stressAtD(8);
}

}  // namespace
}  // namespace tetskin::test
