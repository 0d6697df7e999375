// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The model builder's level selection with fidelity (ModelBuilder.cpp):
// levels are chosen among the faithful candidates (LevelFidelity.h), and a
// level whose target only unfaithful candidates come near is refused with
// the numbers and a way out, unless the user accepts it.

#include <string>
#include <vector>

#include "Candidates.h"

namespace tetskin {

// A level whose nearest candidates are all unfaithful: what is wrong ("level
// 0 (target 600 elements) has no faithful candidate near its target: ...")
// and what would change it ("Ways out: ...").
struct UnfaithfulLevel {
  std::string problem;
  std::string waysOut;
};

struct FaithfulSelection {
  std::vector<int> chosen;  // candidate per target, in target order
  // Those levels take the nearest candidate of any fidelity (written only
  // with --accept-unfaithful).
  std::vector<UnfaithfulLevel> unfaithful;
};

// Per target, the faithful candidate nearest to it (selectLevels over the
// faithful ones). A target with an unfaithful candidate within
// kTargetTolerance of it, but no faithful one, is unfaithful: it takes the
// nearest candidate instead, and says why in `unfaithful`. Throws Error
// when no candidate was meshed at all.
FaithfulSelection selectFaithfulLevels(const Candidates& found, const std::vector<double>& targets,
                                       const BuildOptions& options);

}  // namespace tetskin
