// SPDX-License-Identifier: AGPL-3.0-or-later
#include "FaithfulSelection.h"

#include <cmath>

#include "tetskin/meshing/LevelFidelity.h"
#include "tetskin/meshing/LevelSelection.h"

namespace tetskin {
namespace {

UnfaithfulLevel unfaithfulLevel(std::size_t level, double target, const CandidateReport& nearest,
                                int nearestFaithful, const Candidates& found,
                                const BuildOptions& options) {
  UnfaithfulLevel unfaithful;
  std::string& text = unfaithful.problem;
  text = "level " + std::to_string(level) + " (target " + std::to_string(std::llround(target)) +
         " elements) has no faithful candidate near its target: the nearest, " + nearest.input +
         " " + nearest.label + " with " + std::to_string(nearest.elements) + " elements, " +
         fidelityProblem(*nearest.fidelity);
  if (nearestFaithful >= 0)
    text += "; the nearest faithful candidate has " +
            std::to_string(found.counts[static_cast<std::size_t>(nearestFaithful)]) + " elements";
  std::string& out = unfaithful.waysOut;
  out = "Ways out: ";
  if (nearestFaithful >= 0)
    out += std::string(found.counts[static_cast<std::size_t>(nearestFaithful)] >
                               static_cast<Index>(target)
                           ? "a larger"
                           : "a smaller") +
           " element target (--min-elements/--max-elements), ";
  if (nearest.wrap) out += "--wrap-offset (a shell's thickness) or --wrap-alpha, ";
  if (options.mesher == MesherKind::TetGen) out += "--mesher netgen (remeshes the surface), ";
  if (!options.decimate) out += "--decimate (coarser inputs), ";
  out += "or --accept-unfaithful to write it anyway";
  return unfaithful;
}

}  // namespace

FaithfulSelection selectFaithfulLevels(const Candidates& found, const std::vector<double>& targets,
                                       const BuildOptions& options) {
  std::vector<Index> faithfulCounts = found.counts;
  bool anyFaithful = false;
  for (std::size_t c = 0; c < faithfulCounts.size(); ++c) {
    if (!faithful(found.reports[c])) faithfulCounts[c] = -1;
    anyFaithful = anyFaithful || faithfulCounts[c] >= 0;
  }
  FaithfulSelection selection;
  // (Throws when nothing was meshed at all.)
  const std::vector<int> nearest = selectLevels(found.counts, targets);
  const std::vector<int> nearestFaithful =
      anyFaithful ? selectLevels(faithfulCounts, targets) : std::vector<int>(targets.size(), -1);
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto n = static_cast<std::size_t>(nearest[k]);
    const int f = nearestFaithful[k];
    const bool faithfulNear =
        f >= 0 && withinTargetTolerance(found.counts[static_cast<std::size_t>(f)], targets[k]);
    if (f >= 0 && (faithfulNear || !withinTargetTolerance(found.counts[n], targets[k]))) {
      selection.chosen.push_back(f);
      continue;
    }
    selection.chosen.push_back(nearest[k]);
    selection.unfaithful.push_back(
        unfaithfulLevel(k, targets[k], found.reports[n], f, found, options));
  }
  return selection;
}

}  // namespace tetskin
