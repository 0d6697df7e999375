// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// One simulation run, wired once for every front end: the simulation of a
// dataset level, its scenario, the start (the scenario's or a recorded
// frame's), a surface bound to the level that follows it, the recorder of a
// ParaView time series and the step log. `tetskin simulate`, the animated
// scenes of `render` and `bench`, and tetskin-gui's runner all run through
// it, so what a step does cannot drift between them (issue #52).
//
// Not thread-safe by itself beyond what Simulation guards: the GUI steps it
// on one thread and reads state() and records on another, as Simulation
// allows (its state is taken under its mutex; the recorder and the step log
// are touched by one thread each).

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/io/StepLogFile.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/RunRecorder.h"
#include "tetskin/vtkio/SimulationFrame.h"

namespace tetskin {

class SurfaceDeformer;

// How long a run goes and how often it is written (OptionSchema.h):
// `simulate --steps --every`, `compare --steps --every`, Simulation.record's
// `every`. (The surface's pieces: kPiecesOption, SurfacePieces.h.)
namespace recording_option {
inline constexpr NumberOption kSteps{"steps",      "--steps",  "", "the steps",
                                     "time steps", atLeast(0), 120};
inline constexpr NumberOption kEvery{
    "every",    "--every", "", "the recording interval", "write every k-th step (and the last)",
    atLeast(1), 1};
}  // namespace recording_option

// One of several bodies a run steps as one (a scene's, BodyUnion.h): where
// it lies in the run's level and bound skin, its material, its start and
// whether its skin meets itself.
struct RunBody {
  std::string name;  // "/bodies/1": names it in errors and messages
  BodyRange range;   // nodes and elements of the level (its own numbering), skin vertices
  ElasticMaterial material;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // at the start, m/s
  bool selfContact = false;
};

// What a run is, as a front end has parsed it.
struct RunSpec {
  int level = 0;  // a resolved level of the dataset
  // The front end's options (up axis, gravity, floor, material, solver);
  // the scenario adds its own (scenarioOptions()).
  SimulationOptions options;
  std::string scenario = kDefaultScenario;
  ScenarioParameters parameters;
  std::string datasetName = "dataset";  // names the dataset in errors
  // Every node's velocity at the start (m/s), added to the scenario's.
  Eigen::Vector3d initialVelocity = Eigen::Vector3d::Zero();
  // Several bodies (empty: the level is one body): their materials are
  // options.materialRegions, their skins' self-contact options.
  // skinCollisions.selfBodies; each body's velocity is added to its nodes'
  // at the start, and a bound skin is theirs, body after body.
  std::vector<RunBody> bodies;
};

class SimulationSession {
 public:
  // The simulation of `spec.level` of `dataset` (kept by reference: it
  // must outlive the session), set up by its scenario. Throws Error for an
  // unknown scenario, options the simulation refuses, or a level it refuses.
  SimulationSession(const MultiLevelTetMesh& dataset, const RunSpec& spec);
  ~SimulationSession();
  SimulationSession(const SimulationSession&) = delete;
  SimulationSession& operator=(const SimulationSession&) = delete;

  // Replaces the scenario's start (a drop's lift too) with `start`'s
  // positions and velocities; time stays at 0.
  void startFrom(const FrameState& start);
  // The same from a frame file a run of this level wrote; throws Error
  // naming the file when it is no frame of this level (readSimulationFrame).
  void startFromFrame(const std::filesystem::path& frame);

  // A surface bound to this run's level that follows every state it is
  // asked for (deformedSurface(), recorded frames), and that meets the
  // obstacles as the options' contact points say (Simulation::
  // setContactSkin). `dataset` is the path the binding names
  // (BoundSurface::dataset).
  void bindSurface(SurfaceMesh surface, SurfaceBinding binding, std::string dataset);
  // Whether the run's contact needs a skin bound (bindSurface): it has a
  // floor or obstacles, several bodies, or a skin that meets itself. A
  // front end that draws a skin of its own binds it then.
  bool contactNeedsSkin() const {
    const SimulationOptions& o = options();
    return o.hasContact() || bodies_.size() > 1 || o.skinCollisions.self ||
           !o.skinCollisions.selfBodies.empty();
  }
  bool hasSurface() const { return bound_ != nullptr; }
  // The bound surface deformed to `positions` of the level's nodes.
  const BoundSurface& deformedSurface(const Points3& positions);

  // The static equilibrium under the scenario's loads and targets for the
  // step that starts now (Simulation::solveStatic, with the bound surface
  // meeting the floor and obstacles): the run rests there, time unchanged.
  // Throws Error when there is none (a free body under a net load).
  StaticStats solveStatic();

  // One step: the scenario's forces and targets for the step that starts
  // now, `extraForces` (per level node, e.g. the GUI's pull) added, the
  // implicit step; then a log row when the log is kept. Throws Error when
  // the step fails (the simulation keeps its last good state).
  StepStats step(const Points3* extraForces = nullptr);
  // Wall-clock seconds of the last step (0 before the first).
  double lastStepSeconds() const { return lastStepSeconds_; }

  // `steps` steps (step()), recording every `every`-th and the last one
  // while recording; `afterStep(i, stats)` after step i (from 0). A step
  // that fails throws its Error, the frames before it recorded.
  void run(int steps, int every, const std::function<void(int, const StepStats&)>& afterStep = {});
  // One step (step()), its state recorded while recording when the run's
  // step count is a multiple of `every`: a run stepped a few steps at a time
  // (Python's step(n)) records every `every`-th step of the whole run.
  StepStats stepRecordingEvery(int every, const Points3* extraForces = nullptr);

  // The run's warnings not taken yet, each once, in the words of a front
  // end whose user names options by `names` (OptionSchema.h): nodes that
  // start below the floor (after the start and each startFrom), and the
  // steps whose solve stopped at the iteration limit (again when their
  // count grows). The one channel every front end shows them through. To
  // be called by one thread.
  std::vector<std::string> takeWarnings(OptionNames names);

  // The step log: a row for the start (when keeping begins) and one per
  // step from then on.
  void keepStepLog();
  const std::vector<StepLogRow>& stepLog() const { return log_; }

  // Records the run as a time series at `pvd` (RunRecorder) from the next
  // recordFrame() on, the surface's frames in `surfacePieces` pieces;
  // replaces a recording in progress.
  void record(const std::filesystem::path& pvd, int surfacePieces = 1);
  bool recording() const { return recorder_ != nullptr; }
  // Ends the recording; the series stays as written.
  void stopRecording() { recorder_.reset(); }
  const RunRecorder* recorder() const { return recorder_.get(); }
  // Adds `state` (by default the current one) to the recording, with the
  // bound surface: `drawnSurface` if the front end has deformed it already
  // (a render path), else the session's own deformation of it; the surface
  // frame carries the state's stress and strain (surfaceFields), and the
  // frame the obstacles posed at the state's time (RunRecorder::addFrame).
  void recordFrame(const std::optional<SimulationState>& state = std::nullopt,
                   const BoundSurface* drawnSurface = nullptr);

  // The elements' von Mises stress and equivalent strain in `fields` (a
  // frame of this run) carried to the surface `binding` binds to this
  // run's level, as VonMisesStress and EquivalentStrain (SkinFields.h).
  std::vector<PointScalars> surfaceFields(const FrameFields& fields,
                                          const SurfaceBinding& binding) const;

  Simulation& simulation() { return *simulation_; }
  const Simulation& simulation() const { return *simulation_; }
  const Scenario& scenario() const { return *scenario_; }
  // The run's bodies (empty: one body, the whole level).
  const std::vector<RunBody>& bodies() const { return bodies_; }
  // The options the run uses (the front end's, with the scenario's own).
  const SimulationOptions& options() const { return simulation_->options(); }
  int level() const { return level_; }
  const std::string& datasetName() const { return datasetName_; }
  // The state now (taken under the simulation's mutex).
  SimulationState state() const { return simulation_->state(); }

 private:
  const MultiLevelTetMesh& dataset_;
  int level_;
  std::string datasetName_;
  std::vector<RunBody> bodies_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<Scenario> scenario_;
  std::unique_ptr<BoundSurface> bound_;
  std::unique_ptr<SurfaceDeformer> deformer_;
  Points3 allNodes_;  // the dataset's nodes with the level's moved (the deformer's input)
  std::unique_ptr<RunRecorder> recorder_;
  bool startToWarn_ = true;         // a start not yet looked at for nodes below the floor
  Index shortfallWarnedSteps_ = 0;  // the shortfall's step count last warned of
  bool keepLog_ = false;
  std::vector<StepLogRow> log_;
  double lastStepSeconds_ = 0;

  void logRow(Index step, const StepStats* stats, double seconds);
};

}  // namespace tetskin
