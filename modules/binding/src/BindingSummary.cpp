// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/binding/BindingSummary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/core/Spread.h"

namespace tetskin {

BindingSummary summarizeBinding(const SurfaceBinding& b, double diagonal) {
  BindingSummary s;
  s.vertices = b.vertexCount();
  s.diagonal = diagonal;
  if (s.vertices == 0) return s;
  Index inside = 0;
  std::vector<double> distances(static_cast<std::size_t>(s.vertices));
  for (Index v = 0; v < s.vertices; ++v) {
    inside += b.minBarycentric[v] >= 0 ? 1 : 0;
    distances[static_cast<std::size_t>(v)] =
        std::abs(b.distance[v]) / (diagonal > 0 ? diagonal : 1);
  }
  s.shareInside = static_cast<double>(inside) / static_cast<double>(s.vertices);
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  auto percentile = [&](double p) { return percentileOfSorted(sorted, p); };
  s.distanceP50 = percentile(0.50);
  s.distanceP90 = percentile(0.90);
  s.distanceP99 = percentile(0.99);
  s.distanceMax = sorted.back();
  std::vector<Index> order(static_cast<std::size_t>(s.vertices));
  std::iota(order.begin(), order.end(), 0);
  const std::size_t k = std::min<std::size_t>(5, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](Index a, Index c) { return b.minBarycentric[a] < b.minBarycentric[c]; });
  s.worstBarycentric.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](Index a, Index c) {
                      return distances[static_cast<std::size_t>(a)] >
                             distances[static_cast<std::size_t>(c)];
                    });
  s.worstDistance.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
  return s;
}

std::string misfitWarning(const BindingSummary& s, double controlDiagonal,
                          const std::string& control) {
  const double share = s.distanceP90 * s.diagonal / controlDiagonal;
  if (!(share > kMisfitDistance)) return {};
  return "a tenth of the vertices lie more than " + formatNumber(std::round(100 * share)) +
         "% of " + control +
         "'s diagonal from its boundary: is the surface the dataset's object, placed and scaled "
         "as it is?";
}

std::string misfitWarning(const BindingSummary& s, const MultiLevelTetMesh& mesh, int level) {
  const LevelRange& range = mesh.levels.at(static_cast<std::size_t>(level));
  const Points3 nodes = mesh.nodes.middleRows(range.firstNode, range.nodeCount);
  return misfitWarning(s, boundingBox(nodes).diagonal(), "level " + std::to_string(level));
}

std::string formatSummary(const BindingSummary& s, const SurfaceBinding& b) {
  char line[256];
  std::string out;
  // An embedded vertex is its tetrahedron's barycentric combination: either
  // offset deforms it alike, so naming one would suggest a choice there is not.
  const std::string offset =
      b.method == BindingMethod::Embed ? "" : std::string(", offset ") + toString(b.offset);
  std::snprintf(line, sizeof line, "bound %lld vertices to level %d (method %s%s)\n",
                static_cast<long long>(s.vertices), b.level, toString(b.method), offset.c_str());
  out += line;
  std::snprintf(line, sizeof line, "  all weights >= 0:   %.2f%% of vertices\n",
                100.0 * s.shareInside);
  out += line;
  std::snprintf(line, sizeof line, "  |distance| / diag:  p50 %.2e  p90 %.2e  p99 %.2e  max %.2e\n",
                s.distanceP50, s.distanceP90, s.distanceP99, s.distanceMax);
  out += line;
  out += "  most negative weight:";
  for (Index v : s.worstBarycentric) {
    // (+ 0.0: a coordinate of -0, on an edge, reads 0, not "-0".)
    std::snprintf(line, sizeof line, " v%lld (%.3g)", static_cast<long long>(v),
                  b.minBarycentric[v] + 0.0);
    out += line;
  }
  out += "\n  farthest:";
  for (Index v : s.worstDistance) {
    std::snprintf(line, sizeof line, " v%lld (%.2e)", static_cast<long long>(v),
                  std::abs(b.distance[v]) / (s.diagonal > 0 ? s.diagonal : 1));
    out += line;
  }
  out += "\n";
  return out;
}

}  // namespace tetskin
