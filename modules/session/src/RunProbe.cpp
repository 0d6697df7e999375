// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/RunProbe.h"

#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/spatial/TetLocator.h"
#include "tetskin/vtkio/RecordedRun.h"

namespace tetskin {

RunProbe probeRun(const std::filesystem::path& pvd, const Points3& points,
                  const std::vector<std::string>& pointNames) {
  if (static_cast<Index>(pointNames.size()) != points.rows())
    throw Error("the probe's points: " + std::to_string(points.rows()) + " points, " +
                std::to_string(pointNames.size()) + " names");
  const RecordedRun run(pvd);
  const TetMesh rest = run.rest();
  const TetLocator locator(rest);
  const double reach = 1e-6 * boundingBox(rest.nodes).diagonal();
  RunProbe probe;
  std::vector<Eigen::Vector4d> weights;
  for (Index p = 0; p < points.rows(); ++p) {
    const Eigen::Vector3d point = points.row(p).transpose();
    const TetLocation at = locator.locate(point);
    if (at.element < 0 || std::sqrt(at.squaredDistance) > reach)
      throw Error(pointNames[static_cast<std::size_t>(p)] + ": the point " + commaSeparated(point) +
                  " lies outside the run's control mesh (" +
                  formatNumber(std::sqrt(at.squaredDistance)) + " from its nearest element)");
    probe.elements.push_back(at.element);
    weights.push_back(at.barycentric);
  }
  const std::string restName = "the first frame of " + pvd.string();
  for (std::size_t f = 0; f < run.frameCount(); ++f) {
    const FrameState state = run.read(f, rest, restName);
    Points3 displacement(points.rows(), 3);
    SymmetricTensors stress(state.stress.rows() > 0 ? points.rows() : 0, 6);
    Eigen::VectorXd vonMises = Eigen::VectorXd::Constant(points.rows(), std::nan(""));
    for (Index p = 0; p < points.rows(); ++p) {
      const int e = probe.elements[static_cast<std::size_t>(p)];
      Eigen::RowVector3d u = Eigen::RowVector3d::Zero();
      for (int k = 0; k < 4; ++k) {
        const int node = rest.elements(e, k);
        u += weights[static_cast<std::size_t>(p)][k] *
             (state.positions.row(node) - rest.nodes.row(node));
      }
      displacement.row(p) = u;
      if (stress.rows() > 0) stress.row(p) = state.stress.row(e);
      if (state.vonMisesStress.size() > 0) vonMises[p] = state.vonMisesStress[e];
    }
    probe.times.push_back(run.time(f));
    probe.displacements.push_back(std::move(displacement));
    probe.stresses.push_back(std::move(stress));
    probe.vonMises.push_back(std::move(vonMises));
  }
  return probe;
}

}  // namespace tetskin
