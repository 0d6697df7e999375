// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/meshing/LevelSelection.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

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

bool withinTargetTolerance(Index elements, double target) {
  const double ratio = static_cast<double>(elements) / target;
  return ratio <= kTargetTolerance && ratio >= 1 / kTargetTolerance;
}

std::vector<std::string> selectionWarnings(const std::vector<Index>& elementCounts,
                                           const std::vector<int>& chosen,
                                           const std::vector<double>& targets) {
  std::vector<std::string> warnings;
  auto count = [&](std::size_t level) {
    return elementCounts[static_cast<std::size_t>(chosen[level])];
  };
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    if (k > 0 && chosen[k] == chosen[k - 1])
      warnings.push_back("levels " + std::to_string(k - 1) + " and " + std::to_string(k) +
                         " are the same candidate (" + std::to_string(count(k)) + " elements)");
    if (k >= targets.size()) continue;
    if (withinTargetTolerance(count(k), targets[k])) continue;
    const double ratio = static_cast<double>(count(k)) / targets[k];
    // "269x" or "4.5x" its target; "1/24" or "1/2.5" of it.
    const double factor = ratio > 1 ? ratio : 1 / ratio;
    std::ostringstream shown;
    shown << std::fixed << std::setprecision(factor < 10 ? 1 : 0) << factor;
    std::ostringstream line;
    line << "level " << k << " has " << count(k) << " elements, "
         << (ratio > 1 ? shown.str() + "x" : "1/" + shown.str() + " of") << " its target of "
         << std::llround(targets[k]);
    warnings.push_back(line.str());
  }
  return warnings;
}

}  // namespace tetskin
