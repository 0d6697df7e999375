// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/SimulationRunner.h"

#include <chrono>
#include <utility>

namespace tetskin {

SimulationRunner::SimulationRunner(const MultiLevelTetMesh& dataset, const RunSpec& spec, Pace pace)
    : session_(dataset, spec), pace_(pace) {
  pull_ = Points3::Zero(session_.simulation().restMesh().nodeCount(), 3);
  thread_ = std::thread([this] { loop(); });
}

SimulationRunner::~SimulationRunner() {
  quit_ = true;
  wake_.notify_all();
  thread_.join();
}

void SimulationRunner::play() {
  playing_ = true;
  wake_.notify_all();
}

void SimulationRunner::pause() {
  playing_ = false;
}

void SimulationRunner::step() {
  if (!playing_) stepOnce();
}

StaticStats SimulationRunner::solveStatic() {
  pause();
  std::lock_guard<std::mutex> lock(stepMutex_);
  return session_.solveStatic();
}

Index SimulationRunner::steps() const {
  return session_.simulation().steps();
}

void SimulationRunner::pull(const std::vector<int>& nodes, const Points3& forces) {
  std::lock_guard<std::mutex> lock(pullMutex_);
  pull_.setZero();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    pull_.row(nodes[i]) += forces.row(static_cast<Index>(i));
}

void SimulationRunner::release() {
  std::lock_guard<std::mutex> lock(pullMutex_);
  pull_.setZero();
}

StepStats SimulationRunner::lastStats() const {
  std::lock_guard<std::mutex> lock(statsMutex_);
  return lastStats_;
}

void SimulationRunner::stepOnce() {
  std::lock_guard<std::mutex> lock(stepMutex_);
  try {
    // The scenario's forces (set anew each step) plus the user's pull.
    Points3 pull;
    {
      std::lock_guard<std::mutex> pullLock(pullMutex_);
      pull = pull_;
    }
    const StepStats stats = session_.step(&pull);
    std::lock_guard<std::mutex> statsLock(statsMutex_);
    lastStats_ = stats;
  } catch (const std::exception& e) {
    playing_ = false;
    std::lock_guard<std::mutex> failureLock(failureMutex_);
    failure_ = e.what();
    return;
  }
  lastStepSeconds_ = session_.lastStepSeconds();
}

std::optional<std::string> SimulationRunner::takeFailure() {
  std::lock_guard<std::mutex> lock(failureMutex_);
  return std::exchange(failure_, std::nullopt);
}

void SimulationRunner::loop() {
  using Clock = std::chrono::steady_clock;
  const auto dt = std::chrono::duration<double>(session_.options().timeStep);
  auto next = Clock::now();
  while (!quit_) {
    if (!playing_) {
      std::unique_lock<std::mutex> lock(waitMutex_);
      wake_.wait_for(lock, std::chrono::milliseconds(50), [this] { return quit_ || playing_; });
      next = Clock::now();
      continue;
    }
    stepOnce();
    if (pace_ == Pace::Unpaced) continue;
    // Real time at most: simulated seconds do not run ahead of the clock.
    next += std::chrono::duration_cast<Clock::duration>(dt);
    if (next > Clock::now())
      std::this_thread::sleep_until(next);
    else
      next = Clock::now();
  }
}

}  // namespace tetskin
