// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A run (SimulationSession) stepped on a thread of its own: tetskin-gui's
// simulation, in parallel with the drawing (the report expected this to raise
// the frame rate), and the soak test's. play runs steps, paced to real time
// or as fast as they go; pause stops after the current step; step() runs one.
// The GUI thread reads the latest state and sets pulling forces at any time
// (Simulation guards both with its mutex). A step that fails (the
// simulation diverged) pauses the runner, keeps the last good state and
// leaves its message for takeFailure(): an exception must not leave the
// thread, where it would end the program.

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "tetskin/session/SimulationSession.h"

namespace tetskin {

class SimulationRunner {
 public:
  enum class Pace {
    RealTime,  // simulated seconds never run ahead of the clock (the GUI)
    Unpaced,   // each step as soon as the last is done
  };

  // The run `spec` of `dataset` (SimulationSession). Throws Error for an
  // unknown scenario, bad options or a level the simulation refuses.
  SimulationRunner(const MultiLevelTetMesh& dataset, const RunSpec& spec,
                   Pace pace = Pace::RealTime);
  ~SimulationRunner();

  void play();
  void pause();
  bool playing() const { return playing_; }
  // One step now (waits for it); only while paused.
  void step();
  // Pauses, waits for a step in progress, and moves the run to its static
  // equilibrium (SimulationSession::solveStatic); throws its Error.
  StaticStats solveStatic();
  Index steps() const;
  SimulationState state() const { return session_.state(); }
  Simulation& simulation() { return session_.simulation(); }
  // The run (its recorder is the GUI thread's to use; steps are this one's).
  SimulationSession& session() { return session_; }
  double lastStepSeconds() const { return lastStepSeconds_; }
  // What the last step did (its contacts, solver, times); zeros before the first.
  StepStats lastStats() const;
  // Why the last failed step failed (once; nullopt when none failed since
  // the last call).
  std::optional<std::string> takeFailure();
  // Pulls the level-local `nodes` with `forces` (rows) until released.
  void pull(const std::vector<int>& nodes, const Points3& forces);
  void release();

 private:
  void loop();
  void stepOnce();

  SimulationSession session_;
  Pace pace_;
  Points3 pull_;  // what the user pulls with now (guarded by pullMutex_)
  std::mutex pullMutex_;
  std::atomic<bool> playing_{false}, quit_{false};
  std::atomic<double> lastStepSeconds_{0};
  std::mutex stepMutex_;  // one step at a time
  std::mutex failureMutex_;
  std::optional<std::string> failure_;  // guarded by failureMutex_
  mutable std::mutex statsMutex_;
  StepStats lastStats_;  // guarded by statsMutex_
  std::mutex waitMutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace tetskin
