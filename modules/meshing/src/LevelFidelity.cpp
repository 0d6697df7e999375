// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/LevelFidelity.h"

#include <cmath>
#include <cstdio>

#include "tetskin/core/Geometry.h"
#include "tetskin/spatial/SurfaceDistance.h"

namespace tetskin {

double elementSize(double meanElementVolume) {
  return std::cbrt(6.0 * std::sqrt(2.0) * meanElementVolume);
}

double elementSize(const TetMesh& mesh) {
  if (mesh.elementCount() == 0) return 0;
  double volume = 0;
  for (Index e = 0; e < mesh.elementCount(); ++e) volume += std::abs(elementVolume(mesh, e));
  return elementSize(volume / static_cast<double>(mesh.elementCount()));
}

LevelFidelity measureFidelity(const SurfaceMesh& input, const SurfaceMesh& boundary,
                              double elementSize) {
  const OneSidedDistance in = oneSidedDistance(input, boundary);
  const OneSidedDistance out = oneSidedDistance(boundary, input);
  LevelFidelity f;
  f.diagonal = boundingBox(input).diagonal();
  f.elementSize = elementSize;
  f.inputToLevelMax = in.max;
  f.inputToLevelMean = in.mean;
  f.levelToInputMax = out.max;
  f.levelToInputMean = out.mean;
  f.boundMean = kFidelityMeanShare * f.elementSize;
  f.boundMax = kFidelityMaxShare * f.elementSize;
  f.faithful = f.inputToLevelMean <= f.boundMean && f.inputToLevelMax <= f.boundMax;
  return f;
}

std::string fidelityProblem(const LevelFidelity& f) {
  const double d = f.diagonal > 0 ? f.diagonal : 1.0;
  char text[200];
  std::string problem;
  if (f.inputToLevelMean > f.boundMean) {
    std::snprintf(text, sizeof text,
                  "lies off the input by %.2g%% of the diagonal on average (at most %.2g%% for "
                  "its element size %.2g%%)",
                  100 * f.inputToLevelMean / d, 100 * f.boundMean / d, 100 * f.elementSize / d);
    problem = text;
  }
  if (f.inputToLevelMax > f.boundMax) {
    std::snprintf(text, sizeof text,
                  "%s%.2g%% of the diagonal at worst (at most %.2g%% for its element size %.2g%%)",
                  problem.empty() ? "lies off the input by " : ", and by ",
                  100 * f.inputToLevelMax / d, 100 * f.boundMax / d, 100 * f.elementSize / d);
    problem += text;
  }
  return problem;
}

}  // namespace tetskin
