// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/deformation/SurfaceFields.h"

#include <cmath>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

Eigen::VectorXd nodeMeans(const TetMesh& level, const Eigen::VectorXd& elementValues) {
  if (elementValues.size() != level.elementCount())
    throw Error(std::to_string(elementValues.size()) + " element values for a level of " +
                std::to_string(level.elementCount()) + " elements");
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(level.nodeCount());
  Eigen::VectorXd volume = Eigen::VectorXd::Zero(level.nodeCount());
  for (Index e = 0; e < level.elementCount(); ++e) {
    const double v = std::abs(elementVolume(level, e));
    for (int k = 0; k < 4; ++k) {
      const int node = level.elements(e, k);
      sum[node] += v * elementValues[e];
      volume[node] += v;
    }
  }
  return (volume.array() > 0).select(sum.array() / volume.array(), 0.0);
}

Eigen::VectorXd boundValues(const SurfaceBinding& binding, Index firstNode,
                            const Eigen::VectorXd& nodeValues) {
  Eigen::VectorXd values(binding.vertexCount());
  const int controls = binding.controlsPerVertex();
  for (Index v = 0; v < binding.vertexCount(); ++v) {
    double value = 0;
    for (int k = 0; k < controls; ++k) {
      const Index node = binding.controlIds(v, k) - firstNode;
      if (node < 0 || node >= nodeValues.size())
        throw Error("surface vertex " + std::to_string(v) + " is bound to node " +
                    std::to_string(binding.controlIds(v, k)) + ", outside the level's " +
                    std::to_string(nodeValues.size()) + " nodes from " + std::to_string(firstNode));
      value += binding.weights(v, k) * nodeValues[node];
    }
    values[v] = value;
  }
  return values;
}

}  // namespace tetskin
