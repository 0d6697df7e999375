// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The bodies the simulation tests run: a cantilever with its Euler-Bernoulli
// answers (deflection under its weight and a tip load, first natural
// frequency), a free bar pulled at both ends, and helpers to load, hold and
// measure them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <regex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ExpectError.h"
#include "SampleData.h"
#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin::test {
inline MultiLevelTetMesh oneLevel(const TetMesh& mesh) {
  MultiLevelTetMesh m;
  appendLevel(m, mesh);
  return m;
}

inline std::vector<int> nodesWithXBelow(const TetMesh& mesh, double x) {
  std::vector<int> nodes;
  for (Index v = 0; v < mesh.nodeCount(); ++v)
    if (mesh.nodes(v, 0) <= x) nodes.push_back(static_cast<int>(v));
  return nodes;
}

// A cantilever along x, clamped at x = 0, for the Euler-Bernoulli tests:
// linear tetrahedra are too stiff in bending and converge from below (under
// its own weight 40x4x4 cubes give -17%, 60x6x6 -8%, 80x8x8 -4.4%).
inline constexpr double kBeamLength = 10, kBeamWidth = 1, kBeamHeight = 1;
inline constexpr double kBeamInertia =
    kBeamWidth * kBeamHeight * kBeamHeight * kBeamHeight / 12;  // I

// The nodes of the free end (x = L).
inline std::vector<Index> freeEnd(const TetMesh& beam) {
  std::vector<Index> end;
  for (Index v = 0; v < beam.nodeCount(); ++v)
    if (beam.nodes(v, 0) >= kBeamLength - 1e-9) end.push_back(v);
  return end;
}

// The beam clamped at x = 0 (no base: it is a share of the height) with a
// load of P newtons down spread over the free end.
inline ScenarioParameters tipLoaded(const TetMesh& beam, double P) {
  ScenarioParameters p;
  p.baseShare = 0;
  p.fixedNodes = nodesWithXBelow(beam, 1e-9);
  p.loads = Points3::Zero(beam.nodeCount(), 3);
  const std::vector<Index> end = freeEnd(beam);
  for (Index v : end) p.loads(v, 1) = -P / static_cast<double>(end.size());
  return p;
}

// The free end's mean downward deflection.
inline double tipDeflection(const TetMesh& beam, const Points3& positions) {
  const std::vector<Index> end = freeEnd(beam);
  double tip = 0;
  for (Index v : end) tip += beam.nodes(v, 1) - positions(v, 1);
  return tip / static_cast<double>(end.size());
}

// The beams' material: E = 1e6 Pa, no Poisson effect (Euler-Bernoulli
// has none), density 1, damping by the mass only.
inline ElasticMaterial beamMaterial(double massDamping) {
  ElasticMaterial material;
  material.youngsModulus = 1e6;
  material.poissonRatio = 0.0;
  material.density = 1;
  material.massDamping = massDamping;
  material.stiffnessDamping = 0;
  return material;
}

// The dynamics tests' beam: weightless and undamped but for backward
// Euler's own damping, about 60 steps per period of its first mode.
inline SimulationOptions swingingBeamOptions() {
  SimulationOptions options;
  options.material = beamMaterial(0);
  options.gravity.setZero();
  options.timeStep = 0.01;
  options.tolerance = 1e-7;
  return options;
}

// Euler-Bernoulli's first natural frequency of the cantilever,
// (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)), in Hz.
inline double firstNaturalFrequency(const ElasticMaterial& material) {
  const double A = kBeamWidth * kBeamHeight;
  return 1.8751 * 1.8751 / (2 * M_PI) *
         std::sqrt(material.youngsModulus * kBeamInertia /
                   (material.density * A * std::pow(kBeamLength, 4)));
}

// Euler-Bernoulli's tip deflection under a tip load P, P L^3 / (3 E I).
inline double tipLoadDeflection(const ElasticMaterial& material, double P) {
  return P * std::pow(kBeamLength, 3) / (3 * material.youngsModulus * kBeamInertia);
}

// Runs `beam` in the sag scenario with `p` (its held nodes, loads and load
// curve) until `until` seconds, checking that each step's external forces
// are the loads times the curve's factor at the step's start; the largest
// |tip deflection| after `from` seconds.
inline double peakTipDeflection(const TetMesh& beam, const SimulationOptions& options,
                                const ScenarioParameters& p, double from, double until) {
  Simulation sim(oneLevel(beam), 0, options);
  const auto sag = makeScenario("sag", p);
  sag->setUp(sim);
  double peak = 0;
  while (sim.time() < until) {
    const double t = sim.time();
    sag->beforeStep(sim, t);
    EXPECT_TRUE(sim.externalForces().isApprox(p.loadCurve.factorAt(t) * p.loads)) << "t = " << t;
    sim.step();
    if (sim.time() > from)
      peak = std::max(peak, std::abs(tipDeflection(beam, sim.state().positions)));
  }
  return peak;
}

inline TetMesh cantilever() {
  return test::tetGrid(80, 8, 8, {kBeamLength, kBeamHeight, kBeamWidth});
}

// Large implicit steps, heavily damped, march to the static equilibrium.
inline SimulationOptions staticBeamOptions() {
  SimulationOptions options;
  options.material = beamMaterial(5);
  options.timeStep = 1.0;
  options.tolerance = 1e-10;
  options.solver = SolverKind::ConjugateGradient;
  return options;
}

// Steps until the tip (the nodes at x = L) settles; its mean downward
// deflection. `scenario`, if any, is set up and drives each step.
inline double settledTipDeflection(Simulation& sim, Scenario* scenario) {
  const TetMesh& beam = sim.restMesh();
  if (scenario) scenario->setUp(sim);
  double previous = 0, tip = 0;
  for (int i = 0; i < 60; ++i) {
    if (scenario) scenario->beforeStep(sim, sim.time());
    sim.step();
    tip = tipDeflection(beam, sim.state().positions);
    if (std::abs(tip - previous) < 1e-9 * std::abs(tip)) break;
    previous = tip;
  }
  return tip;
}

// A free 6 x 1 x 1 bar (E = 1e6 Pa, density 1) pulled at both ends by an
// axial stress of 1e-3 E: opposite end forces, equal on each of the 16 end
// nodes.
inline const TetMesh& pulledBar() {
  static const TetMesh bar = test::tetGrid(12, 3, 3, {6, 1, 1});
  return bar;
}

inline SimulationOptions pulledBarOptions(double poissonRatio, double timeStep) {
  SimulationOptions options;
  options.gravity.setZero();
  options.material.youngsModulus = 1e6;
  options.material.poissonRatio = poissonRatio;
  options.material.density = 1;
  options.material.massDamping = 5;
  options.material.stiffnessDamping = 0;
  options.timeStep = timeStep;
  options.tolerance = 1e-10;
  options.solver = SolverKind::ConjugateGradient;
  return options;
}

inline void pullBar(Simulation& sim) {
  const TetMesh& bar = sim.restMesh();
  Points3 forces = Points3::Zero(bar.nodeCount(), 3);
  for (Index v = 0; v < bar.nodeCount(); ++v) {
    if (bar.nodes(v, 0) < 1e-9) forces(v, 0) = -1e3 / 16;
    if (bar.nodes(v, 0) > 6 - 1e-9) forces(v, 0) = 1e3 / 16;
  }
  sim.setExternalForces(forces);
}

}  // namespace tetskin::test
