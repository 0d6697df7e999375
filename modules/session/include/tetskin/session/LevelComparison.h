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
//
// A scene compares its levels too: every body on the same level, the
// scene's skins bound as loadScene binds them, its obstacles and contact
// in every run; the errors are also told per body (each body's skin
// vertices, against its own diagonal).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/Spread.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/deformation/SurfaceComparison.h"
#include "tetskin/session/SceneRun.h"
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

// One level of a scene to compare: the scene loaded with every body on
// it, and its run as the front end resolved it.
struct SceneLevel {
  int level = 0;  // the level compared (the first body's numbering)
  SceneRun scene;
  RunSpec spec;
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
  // Simulates a scene on each of `levels`, `levels[reference]` the
  // reference. Throws Error for fewer than two levels, a reference out of
  // range, a level whose skins differ from the reference's (a body without
  // a surface takes its level's boundary), or what a run refuses.
  LevelComparison(std::vector<SceneLevel> levels, std::size_t reference);
  ~LevelComparison();
  LevelComparison(const LevelComparison&) = delete;
  LevelComparison& operator=(const LevelComparison&) = delete;

  std::size_t runCount() const { return runs_.size(); }
  std::size_t reference() const { return reference_; }
  int level(std::size_t run) const;
  // The tetrahedra a run simulates (a scene's: every body's).
  Index elementCount(std::size_t run) const;
  bool simulated() const { return recorded_.empty(); }
  // Recorded runs: their frames (compare() at each, advance() between).
  std::size_t recordedFrames() const;
  // The surface's bounding-box diagonal at rest: what relative errors are of.
  double diagonal() const { return diagonal_; }
  // The bodies whose skins make the surface (one for a dataset's: every
  // vertex), their skin vertices (BodyRange's vertex range), and each
  // body's skin's diagonal at rest.
  std::size_t bodyCount() const { return bodies_.size(); }
  const BodyRange& body(std::size_t body) const { return bodies_.at(body); }
  double bodyDiagonal(std::size_t body) const { return bodyDiagonals_.at(body); }
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
  // The same over one body's skin vertices.
  ErrorSpread overall(std::size_t run, std::size_t body) const;
  // A run's mean wall-clock seconds per step over the whole comparison (0
  // for recorded runs or before a step).
  double meanStepSeconds(std::size_t run) const;

  // The frames' errors as a table (.csv, written atomically): a row per
  // frame and run: frame, time, run, level, step_ms, then max, p99 and
  // median of distance, relative distance and normal angle (degrees). With
  // several bodies, a row per frame, run and body, with a last column body
  // (relative distances of the body's diagonal).
  void writeFrameTable(const std::filesystem::path& csv) const;

 private:
  struct Run;
  SurfaceMesh surface_;
  std::string datasetPath_;
  std::size_t reference_ = 0;
  double diagonal_ = 0;
  std::vector<BodyRange> bodies_;
  std::vector<double> bodyDiagonals_;
  std::vector<std::unique_ptr<Run>> runs_;
  std::vector<RecordedRun> recorded_;  // empty when simulated
  std::size_t recordedFrame_ = 0;
  std::unique_ptr<RunRecorder> recorder_;
  std::vector<ComparedFrame> frames_;

  // The surface and its bodies (one: the whole surface, without `bodies`).
  void setSurface(const SurfaceMesh& surface, const std::vector<RunBody>& bodies);
  // A run of `level` of `dataset`, the surface bound to it by `binding`.
  void addRun(const MultiLevelTetMesh& dataset, int level, SurfaceBinding binding);
  void bind(const MultiLevelTetMesh& dataset, int level);
  Points3 currentPositions(std::size_t run) const;
  // Per frame, per run and body: the errors of the body's vertices.
  ErrorSpread frameErrors(std::size_t frame, std::size_t run, std::size_t body) const;
  // A compared frame's values (a run's distances or angles, kept frame
  // after frame) of a body's vertices.
  std::span<const float> bodyValues(const std::vector<float>& values, std::size_t frame,
                                    std::size_t body) const;
};

}  // namespace tetskin
