// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Choosing the dataset's levels among the meshed candidates (report section
// 2.5): level k of L targets min * (max/min)^(k/(L-1)) elements, and takes the
// candidate whose element count is closest, searching from the highest
// quality of the finest input first, so that on equal distance the best
// quality for that element count wins.

#include <string>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin {

// Element-count targets for levels 0 (coarsest) .. levels-1; one level targets max.
std::vector<double> levelTargets(Index minElements, Index maxElements, int levels);

// `elementCounts` in search order (finest input first, highest quality first);
// negative entries are failed candidates and never chosen. Returns, per
// target, the index of the chosen candidate. Throws Error when no candidate
// succeeded.
std::vector<int> selectLevels(const std::vector<Index>& elementCounts,
                              const std::vector<double>& targets);

// What is wrong with a selection, one line each (without "warning: "):
// neighbouring levels that are the same candidate, and levels whose count
// is more than kTargetTolerance away from their target (either way).
// `chosen` is per level, coarsest first, and targets[k] is level k's.
// Empty when the selection is as asked.
constexpr double kTargetTolerance = 2.0;
// Whether `elements` lies within kTargetTolerance of `target`, either way.
bool withinTargetTolerance(Index elements, double target);
std::vector<std::string> selectionWarnings(const std::vector<Index>& elementCounts,
                                           const std::vector<int>& chosen,
                                           const std::vector<double>& targets);

}  // namespace tetskin
