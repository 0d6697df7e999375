// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Which control level is enough (issue #55): the same motion on several
// levels of one dataset, the same surface bound to each, and per frame how
// far each level's deformed surface lies from the reference level's, vertex
// by vertex (distance, and the angle between normals), with each level's
// cost per step beside it. Wired once for `tetskin compare` and the GUI's
// Compare panel.
//
// The motion is either simulated here (one SimulationSession per level, the
// same scenario and options) or read from runs recorded earlier (their
// frames matched one by one). The surface is bound to every level by the
// closest boundary point with the normal offset: exact at rest and under
// rigid motion, so two levels that move alike deform it alike, and what
// differs is what the levels' motions differ by.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tetskin/core/Spread.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/deformation/SurfaceComparison.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/vtkio/BindingFile.h"

namespace tetskin {

class RecordedRun;
class RunRecorder;
class SurfaceDeformer;

// One compared run's errors in one frame (or over all frames): the spread
// of its vertices' distances from the reference's (model units) and of the
// angles between their normals (degrees).
struct ErrorSpread {
  Spread distance, angle;
};

struct ComparedFrame {
  double time = 0;
  Index steps = 0;  // steps taken by each run (0 for recorded runs)
  // Per compared run, in the order given (the reference's are zero).
  std::vector<ErrorSpread> errors;
  // Per run, its mean wall-clock seconds per step since the last frame
  // (0 for recorded runs and the first frame).
  std::vector<double> stepSeconds;
};

class LevelComparison {
 public:
  // Simulates `runs` (each a level, its scenario and options, as simulate
  // runs them) on `dataset`, with `surface` bound to each run's level;
  // `runs[reference]` is the reference. `datasetPath` is what the frames'
  // bindings name (BoundSurface::dataset). Throws Error for fewer than two
  // runs, a reference out of range, or what a run or binding refuses.
  LevelComparison(const MultiLevelTetMesh& dataset, const SurfaceMesh& surface,
                  const std::vector<RunSpec>& runs, std::size_t reference,
                  const std::string& datasetPath);
  // Compares runs recorded earlier (`tetskin simulate`, the GUI's Record),
  // the first the reference, each on the level its frames name. Throws
  // Error naming a run whose frames do not say their level or are not of
  // it, or that has another number of frames or other times than the
  // first.
  LevelComparison(const MultiLevelTetMesh& dataset, const SurfaceMesh& surface,
                  const std::vector<std::filesystem::path>& recordedRuns,
                  const std::string& datasetPath);
  ~LevelComparison();
  LevelComparison(const LevelComparison&) = delete;
  LevelComparison& operator=(const LevelComparison&) = delete;

  std::size_t runCount() const { return runs_.size(); }
  std::size_t reference() const { return reference_; }
  int level(std::size_t run) const;
  bool simulated() const { return recorded_.empty(); }
  // Recorded runs: their frames (compare() at each, advance() between).
  std::size_t recordedFrames() const;
  // The surface's bounding-box diagonal at rest: what relative errors are of.
  double diagonal() const { return diagonal_; }
  Index vertexCount() const { return surface_.vertexCount(); }
  // The simulated run's session (nullptr for recorded runs).
  const SimulationSession* session(std::size_t run) const;

  // Records every compare() from now on as a ParaView series at `pvd`: a
  // part per run, each the surface as bound to that run's level, deformed,
  // with point arrays SurfaceError, RelativeError and NormalAngle (and,
  // simulated, VonMisesStress and EquivalentStrain).
  void record(const std::filesystem::path& pvd);
  const RunRecorder* recorder() const { return recorder_.get(); }

  // Every run to its next state: one step each (simulated), or the next
  // recorded frame. Throws Error when a step fails or no frame is left.
  void advance();
  // Compares the runs' current states: returns this frame's errors (also
  // kept in frames()), leaves each run's deformed surface with its arrays
  // in surface(run), and records the frame where record() was called.
  const ComparedFrame& compare();
  const std::vector<ComparedFrame>& frames() const { return frames_; }
  const BoundSurface& surface(std::size_t run) const;
  const SurfaceErrors& errors(std::size_t run) const;
  // A run's errors over every vertex of every compared frame (kept as
  // floats: to 7 digits).
  ErrorSpread overall(std::size_t run) const;
  // A run's mean wall-clock seconds per step over the whole comparison (0
  // for recorded runs or before a step).
  double meanStepSeconds(std::size_t run) const;

  // The frames' errors as a table (.csv, written atomically): a row per
  // frame and run: frame, time, run, level, step_ms, then max, p99 and
  // median of distance, relative distance and normal angle (degrees).
  void writeFrameTable(const std::filesystem::path& csv) const;

 private:
  struct Run;
  const MultiLevelTetMesh& dataset_;
  SurfaceMesh surface_;
  std::string datasetPath_;
  std::size_t reference_ = 0;
  double diagonal_ = 0;
  std::vector<std::unique_ptr<Run>> runs_;
  std::vector<RecordedRun> recorded_;  // empty when simulated
  std::size_t recordedFrame_ = 0;
  std::unique_ptr<RunRecorder> recorder_;
  std::vector<ComparedFrame> frames_;

  void bind(int level);
  Points3 currentPositions(std::size_t run) const;
};

}  // namespace tetskin
