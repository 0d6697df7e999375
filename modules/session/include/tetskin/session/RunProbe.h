// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A recorded run read at given points (`tetskin probe`, Python's probe):
// each point, in the rest shape's coordinates, is located in the control
// mesh once; in every frame its displacement is interpolated linearly in
// its element (exact for the linear tetrahedra the run was computed on)
// and its stress is its element's (constant in a linear tetrahedron).

#include <filesystem>
#include <string>
#include <vector>

#include "tetskin/core/FrameFields.h"
#include "tetskin/core/Types.h"

namespace tetskin {

struct RunProbe {
  std::vector<double> times;  // per frame, s
  std::vector<int> elements;  // per point: the element of the rest mesh it lies in
  // Per frame, one row per point: m; Pa (xx, yy, zz, xy, yz, xz; empty for
  // frames recorded without the Stress array); Pa.
  std::vector<Points3> displacements;
  std::vector<SymmetricTensors> stresses;
  std::vector<Eigen::VectorXd> vonMises;
};

// Inputs: the run's .pvd, the points (#P x 3, the rest shape's
// coordinates) and a name for each in errors ("points.txt:4"). Throws
// Error naming the .pvd for a run RecordedRun refuses, and naming the point
// for one farther than 1e-6 of the mesh's size outside it.
RunProbe probeRun(const std::filesystem::path& pvd, const Points3& points,
                  const std::vector<std::string>& pointNames);

}  // namespace tetskin
