// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/SurfaceBinding.h"

#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

void SurfaceBinding::resize(Index vertices) {
  controlIds.setConstant(vertices, 4, -1);
  weights.setZero(vertices, 4);
  distance.setZero(vertices);
  faceId.setConstant(vertices, -1);
  minBarycentric.setZero(vertices);
}

void validateBinding(const SurfaceBinding& b, Index surfaceVertices, Index nodeCount,
                     const std::string& name) {
  if (b.controlIds.rows() != surfaceVertices || b.weights.rows() != surfaceVertices ||
      b.distance.size() != surfaceVertices || b.faceId.size() != surfaceVertices ||
      b.minBarycentric.size() != surfaceVertices)
    throw Error(name, 0,
                "the binding has " + std::to_string(b.controlIds.rows()) +
                    " entries for a surface of " + std::to_string(surfaceVertices) + " vertices");
  const int k = b.controlsPerVertex();
  for (Index v = 0; v < surfaceVertices; ++v) {
    double sum = 0;
    for (int c = 0; c < k; ++c) {
      const int id = b.controlIds(v, c);
      if (id < 0 || id >= nodeCount)
        throw Error(name, 0,
                    "vertex " + std::to_string(v) + " is bound to node " + std::to_string(id) +
                        ", outside the dataset's " + std::to_string(nodeCount) + " nodes");
      if (!std::isfinite(b.weights(v, c)))
        throw Error(name, 0, "vertex " + std::to_string(v) + " has a non-finite weight");
      sum += b.weights(v, c);
    }
    if (std::abs(sum - 1.0) > 1e-6)
      throw Error(name, 0,
                  "the weights of vertex " + std::to_string(v) + " sum to " + std::to_string(sum) +
                      ", not 1");
    if (!std::isfinite(b.distance[v]))
      throw Error(name, 0, "vertex " + std::to_string(v) + " has a non-finite distance");
  }
}

}  // namespace tetskin
