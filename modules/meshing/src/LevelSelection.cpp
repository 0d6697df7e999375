// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/LevelSelection.h"

#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"

namespace tetskin {

std::vector<double> levelTargets(Index minElements, Index maxElements, int levels) {
  if (levels < 1) throw Error("the number of levels must be at least 1");
  if (minElements < 1 || maxElements < minElements)
    throw Error("need 1 <= min elements <= max elements, got " + std::to_string(minElements) +
                " and " + std::to_string(maxElements));
  if (levels == 1) return {static_cast<double>(maxElements)};
  std::vector<double> targets(static_cast<std::size_t>(levels));
  const double ratio = static_cast<double>(maxElements) / static_cast<double>(minElements);
  for (int k = 0; k < levels; ++k)
    targets[static_cast<std::size_t>(k)] =
        static_cast<double>(minElements) * std::pow(ratio, static_cast<double>(k) / (levels - 1));
  return targets;
}

std::vector<int> selectLevels(const std::vector<Index>& elementCounts,
                              const std::vector<double>& targets) {
  std::vector<int> chosen;
  for (double target : targets) {
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < elementCounts.size(); ++i) {
      if (elementCounts[i] < 0) continue;
      const double distance = std::abs(static_cast<double>(elementCounts[i]) - target);
      if (distance < bestDistance) {  // strict: the earlier (better) candidate wins ties
        bestDistance = distance;
        best = static_cast<int>(i);
      }
    }
    if (best < 0) throw Error("no candidate mesh was produced, so no level can be chosen");
    chosen.push_back(best);
  }
  return chosen;
}

}  // namespace tetskin
