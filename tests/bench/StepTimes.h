// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One session step timed, and the median of each column over steps: the
// contact benchmarks' rows (contact_bench, bodies_bench).
#include <algorithm>
#include <chrono>
#include <vector>

#include "tetskin/session/SimulationSession.h"

namespace tetskin::bench {

struct StepTimes {
  double step = 0, assembly = 0, solve = 0;  // ms
  int contacts = 0, iterations = 0;
};

inline StepTimes timeStep(SimulationSession& session) {
  const auto start = std::chrono::steady_clock::now();
  const StepStats s = session.step();
  return {
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
      s.assemblySeconds * 1e3, s.solveSeconds * 1e3, s.contacts, s.iterations};
}

// The median of each column of `steps`.
inline StepTimes median(const std::vector<StepTimes>& steps) {
  const auto middle = [&](auto field) {
    std::vector<double> values;
    for (const StepTimes& t : steps) values.push_back(static_cast<double>(t.*field));
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  return {middle(&StepTimes::step), middle(&StepTimes::assembly), middle(&StepTimes::solve),
          static_cast<int>(middle(&StepTimes::contacts)),
          static_cast<int>(middle(&StepTimes::iterations))};
}

// `steps` steps of each session by turns, so that the machine's drift
// (other load, clock changes) falls on all alike: each one's medians.
inline std::vector<StepTimes> stepByTurns(const std::vector<SimulationSession*>& sessions,
                                          int steps) {
  std::vector<std::vector<StepTimes>> times(sessions.size());
  for (int i = 0; i < steps; ++i)
    for (std::size_t k = 0; k < sessions.size(); ++k) times[k].push_back(timeStep(*sessions[k]));
  std::vector<StepTimes> medians;
  for (const std::vector<StepTimes>& t : times) medians.push_back(median(t));
  return medians;
}

}  // namespace tetskin::bench
