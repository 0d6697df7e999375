// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/SolverChoice.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"

namespace tetskin {

namespace {

SolverKind other(SolverKind kind) {
  return kind == SolverKind::Multigrid ? SolverKind::ConjugateGradient : SolverKind::Multigrid;
}

constexpr double kUnlimited = std::numeric_limits<double>::infinity();

}  // namespace

SolverChoice::SolverChoice(int period) : period_(period) {
  if (period < 1) throw Error("solver choice: a sample period of at least one step is needed");
}

bool SolverChoice::isSampleStep(int step) const {
  if (step == 2 || step == 4) return true;
  if (!challengerWins_.empty() && step == lastSample_ + 2) return true;  // confirm a win
  return step > 4 && (step - 4) % period_ == 0;
}

double SolverChoice::preferredMedian() const {
  if (preferredTimes_.empty()) return kUnlimited;
  std::vector<double> times = preferredTimes_;
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

int SolverChoice::shortfalls() const {
  return static_cast<int>(std::count(recentShortfalls_.begin(), recentShortfalls_.end(), 1));
}

SolverChoice::Turn SolverChoice::next() const {
  // (No budget while the preferred itself stops short of the tolerance:
  // its times then bound nothing.)
  if (!isSampleStep(step_) || preferredTimes_.empty()) return {preferred_, false, kUnlimited};
  return {other(preferred_), true,
          shortfalls() > 0 ? kUnlimited : kWinningShare * preferredMedian()};
}

void SolverChoice::makeChallengerPreferred(bool byShortfalls) {
  preferred_ = other(preferred_);
  preferredTimes_ = challengerWins_;  // (its samples: its first times as the preferred)
  recentShortfalls_.clear();
  challengerWins_.clear();
  decidedByShortfalls_ = byShortfalls;
  ++switches_;
}

void SolverChoice::record(double seconds, bool reachedTolerance, bool cutOff) {
  const Turn turn = next();
  const int step = step_++;
  // A step that failed to time (NaN) counts as very slow, not as free.
  if (!(std::isfinite(seconds) && seconds >= 0)) seconds = 1e30;
  if (turn.sample) {
    lastSample_ = step;
    ++samples_;
    cutOffSamples_ += cutOff;
    challengerLastReached_ = reachedTolerance && !cutOff;
    // (A challenger that lost its place by stopping short comes back only
    // when the preferred stops short in turn: its quick samples do not
    // show that its shortfalls are over.)
    const bool win = !decidedByShortfalls_ && challengerLastReached_ &&
                     seconds < turn.budgetSeconds && seconds < kWinningShare * preferredMedian();
    if (!win) {
      challengerWins_.clear();
      return;
    }
    challengerWins_.push_back(seconds);
    if (challengerWins_.size() >= 2) makeChallengerPreferred(false);
    return;
  }
  if (step == 0) return;  // one-time costs: not timed
  recentShortfalls_.push_back(!reachedTolerance);
  if (recentShortfalls_.size() > kWindow) recentShortfalls_.erase(recentShortfalls_.begin());
  if (!reachedTolerance) {
    if (shortfalls() >= 2 && challengerLastReached_) makeChallengerPreferred(true);
    return;
  }
  preferredTimes_.push_back(seconds);
  if (preferredTimes_.size() > kWindow) preferredTimes_.erase(preferredTimes_.begin());
}

}  // namespace tetskin
