// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/SolverChoice.h"

#include <cmath>

#include "tetskin/core/Error.h"

namespace tetskin {

SolverChoice::SolverChoice(int trialSteps, int period) : trialSteps_(trialSteps), period_(period) {
  if (trialSteps < 1 || period < 0)
    throw Error("solver choice: at least one trial step and a period of zero steps or more");
}

SolverKind SolverChoice::next() const {
  if (position_ >= 2 * trialSteps_) return preferred_;
  return (position_ + 2) % 2 == 0 ? SolverKind::ConjugateGradient : SolverKind::Multigrid;
}

void SolverChoice::record(double seconds, bool reachedTolerance) {
  if (position_ < 0) {
    ++position_;
  } else if (position_ < 2 * trialSteps_) {
    // A step that failed to time (NaN) counts as very slow, not as free.
    trialSeconds_[position_ % 2] += std::isfinite(seconds) && seconds >= 0 ? seconds : 1e30;
    if (!reachedTolerance) ++trialShortfalls_[position_ % 2];
    if (++position_ == 2 * trialSteps_) {
      decidedByShortfalls_ = trialShortfalls_[1] != trialShortfalls_[0];
      const bool multigridBetter = decidedByShortfalls_ ? trialShortfalls_[1] < trialShortfalls_[0]
                                                        : trialSeconds_[1] < trialSeconds_[0];
      preferred_ = multigridBetter ? SolverKind::Multigrid : SolverKind::ConjugateGradient;
      trialSeconds_[0] = trialSeconds_[1] = 0;
      trialShortfalls_[0] = trialShortfalls_[1] = 0;
      ++rounds_;
    }
  } else {
    ++position_;
  }
  if (position_ >= 2 * trialSteps_ + period_) position_ = 0;
}

}  // namespace tetskin
