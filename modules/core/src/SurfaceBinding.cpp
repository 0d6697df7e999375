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

const char* toString(BindingMethod method) {
  switch (method) {
    case BindingMethod::Closest:
      return "closest";
    case BindingMethod::Seed:
      return "seed";
    case BindingMethod::Embed:
      return "embed";
  }
  return "?";
}

const char* toString(OffsetMode offset) {
  return offset == OffsetMode::Normal ? "normal" : "displacement";
}

std::optional<BindingMethod> parseBindingMethod(std::string_view text) {
  for (BindingMethod m : {BindingMethod::Closest, BindingMethod::Seed, BindingMethod::Embed})
    if (text == toString(m)) return m;
  return std::nullopt;
}

std::optional<OffsetMode> parseOffsetMode(std::string_view text) {
  for (OffsetMode m : {OffsetMode::Normal, OffsetMode::Displacement})
    if (text == toString(m)) return m;
  return std::nullopt;
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
