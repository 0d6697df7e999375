// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/LevelComparison.h"

#include <cmath>
#include <cstdio>
#include <span>
#include <utility>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/session/SkinFields.h"
#include "tetskin/vtkio/RecordedRun.h"
#include "tetskin/vtkio/RunRecorder.h"

namespace tetskin {

struct LevelComparison::Run {
  int level = 0;                               // the level compared
  std::unique_ptr<SceneRun> scene;             // a scene's level: what dataset points into
  const MultiLevelTetMesh* dataset = nullptr;  // the run's
  int datasetLevel = 0;                        // its level in dataset (a scene's union: 0)
  TetMesh rest;                                // the level at rest, its own numbering
  std::unique_ptr<SimulationSession> session;  // simulated runs
  FrameState recordedState;                    // recorded runs: the current frame
  BoundSurface bound;                          // deformed at the last compare()
  std::unique_ptr<SurfaceDeformer> deformer;
  SurfaceErrors errors;
  // Every compared frame's values, for the spread over the whole run (as
  // floats: a 35k-vertex surface over 121 frames keeps 34 MB a run).
  std::vector<float> distances, angles;
  double stepSeconds = 0, frameStepSeconds = 0;
  Index steps = 0, frameSteps = 0;
};

namespace {

// Two levels or more, the reference one of them.
void checkLevels(std::size_t count, std::size_t reference) {
  if (count < 2)
    throw Error("a comparison needs at least two levels, " + std::to_string(count) + " given");
  if (reference >= count)
    throw Error("the reference is run " + std::to_string(reference) + " of " +
                std::to_string(count));
}

Spread spreadOfValues(const Eigen::VectorXd& values) {
  std::vector<double> copy(values.data(), values.data() + values.size());
  return spreadOf(copy);
}

Spread spreadOfFloats(std::span<const float> values) {
  std::vector<double> copy(values.begin(), values.end());
  return spreadOf(copy);
}

}  // namespace

LevelComparison::LevelComparison(const MultiLevelTetMesh& dataset, const SurfaceMesh& surface,
                                 const std::vector<RunSpec>& runs, std::size_t reference,
                                 const std::string& datasetPath)
    : datasetPath_(datasetPath), reference_(reference) {
  checkLevels(runs.size(), reference);
  setSurface(surface, {});
  for (const RunSpec& spec : runs) {
    bind(dataset, spec.level);
    runs_.back()->session = std::make_unique<SimulationSession>(dataset, spec);
  }
}

LevelComparison::LevelComparison(std::vector<SceneLevel> levels, std::size_t reference)
    : reference_(reference) {
  checkLevels(levels.size(), reference);
  const SceneRun& first = levels[reference].scene;
  if (!first.surface) throw Error(first.scene.file.string() + ": its body has no surface");
  datasetPath_ = first.request.datasetName;
  setSurface(first.surface->surface, first.request.bodies);
  for (SceneLevel& level : levels) {
    auto scene = std::make_unique<SceneRun>(std::move(level.scene));
    const auto sameSkins = [&](const SurfaceMesh& skin) {
      return skin.positions.rows() == surface_.positions.rows() &&
             skin.triangles.rows() == surface_.triangles.rows() &&
             skin.positions == surface_.positions && skin.triangles == surface_.triangles;
    };
    if (!scene->surface || !sameSkins(scene->surface->surface))
      throw Error(scene->scene.file.string() + ": on level " + std::to_string(level.level) +
                  " its skins differ from those on level " +
                  std::to_string(levels[reference].level) +
                  ": give every body a surface, which every level binds");
    addRun(scene->dataset.mesh, scene->level, scene->surface->binding);
    Run& run = *runs_.back();
    run.level = level.level;
    run.session = std::make_unique<SimulationSession>(scene->dataset.mesh, level.spec);
    if (run.session->contactNeedsSkin())
      run.session->bindSurface(surface_, run.bound.binding, datasetPath_);
    run.scene = std::move(scene);
  }
}

LevelComparison::LevelComparison(const MultiLevelTetMesh& dataset, const SurfaceMesh& surface,
                                 const std::vector<std::filesystem::path>& recordedRuns,
                                 const std::string& datasetPath)
    : datasetPath_(datasetPath) {
  if (recordedRuns.size() < 2)
    throw Error("a comparison needs at least two runs, " + std::to_string(recordedRuns.size()) +
                " given");
  setSurface(surface, {});
  for (const std::filesystem::path& path : recordedRuns) {
    const RecordedRun& run = recorded_.emplace_back(path);
    if (!run.level())
      throw Error(path.string(), 0,
                  "its frames do not say which level they are of (no Level array)");
    if (*run.level() < 0 || *run.level() >= dataset.levelCount())
      throw Error(path.string(), 0,
                  "its frames are of level " + std::to_string(*run.level()) +
                      ", which the dataset lacks (levels 0 to " +
                      std::to_string(dataset.levelCount() - 1) + ")");
    const RecordedRun& first = recorded_.front();
    if (run.frameCount() != first.frameCount())
      throw Error(path.string(), 0,
                  "has " + std::to_string(run.frameCount()) + " frames, " + first.path().string() +
                      " " + std::to_string(first.frameCount()) +
                      ": compared runs are matched frame by frame");
    for (std::size_t f = 0; f < run.frameCount(); ++f)
      if (std::abs(run.time(f) - first.time(f)) > 1e-9 * std::max(1.0, std::abs(first.time(f))))
        throw Error(path.string(), 0,
                    "frame " + std::to_string(f) + " is at time " + formatNumber(run.time(f)) +
                        ", in " + first.path().string() + " at " + formatNumber(first.time(f)) +
                        ": compared runs are matched frame by frame");
    bind(dataset, *run.level());
  }
  // Each run at its first frame.
  recordedFrame_ = 0;
  for (std::size_t r = 0; r < runs_.size(); ++r)
    runs_[r]->recordedState =
        recorded_[r].read(0, runs_[r]->rest, "level " + std::to_string(runs_[r]->level));
}

LevelComparison::~LevelComparison() = default;

void LevelComparison::setSurface(const SurfaceMesh& surface, const std::vector<RunBody>& bodies) {
  surface_ = surface;
  diagonal_ = boundingBox(surface_.positions).diagonal();
  for (const RunBody& body : bodies) bodies_.push_back(body.range);
  if (bodies_.empty()) {
    BodyRange all;
    all.vertexCount = surface_.vertexCount();
    all.triangleCount = surface_.triangleCount();
    bodies_.push_back(all);
  }
  for (const BodyRange& body : bodies_)
    bodyDiagonals_.push_back(
        boundingBox(Points3(surface_.positions.middleRows(body.firstVertex, body.vertexCount)))
            .diagonal());
}

void LevelComparison::addRun(const MultiLevelTetMesh& dataset, int level, SurfaceBinding binding) {
  auto run = std::make_unique<Run>();
  run->level = level;
  run->dataset = &dataset;
  run->datasetLevel = level;
  run->rest = extractLevel(dataset, level);
  run->bound.surface = surface_;
  run->bound.binding = std::move(binding);
  run->bound.dataset = datasetPath_;
  run->bound.deformed.emplace(DeformedState{surface_.positions, surface_.normals});
  run->deformer =
      std::make_unique<SurfaceDeformer>(run->bound.surface, run->bound.binding, dataset.nodes,
                                        "the surface on level " + std::to_string(level));
  runs_.push_back(std::move(run));
}

void LevelComparison::bind(const MultiLevelTetMesh& dataset, int level) {
  addRun(dataset, level, bindSurface(surface_, dataset, level));
}

int LevelComparison::level(std::size_t run) const {
  return runs_.at(run)->level;
}

Index LevelComparison::elementCount(std::size_t run) const {
  const Run& r = *runs_.at(run);
  return r.dataset->levels[static_cast<std::size_t>(r.datasetLevel)].elementCount;
}

std::size_t LevelComparison::recordedFrames() const {
  return recorded_.empty() ? 0 : recorded_.front().frameCount();
}

const SimulationSession* LevelComparison::session(std::size_t run) const {
  return runs_.at(run)->session.get();
}

void LevelComparison::record(const std::filesystem::path& pvd) {
  recorder_.reset();
  recorder_ = std::make_unique<RunRecorder>(pvd);
}

void LevelComparison::advance() {
  if (simulated()) {
    for (const auto& run : runs_) {
      run->session->step();
      run->stepSeconds += run->session->lastStepSeconds();
      run->frameStepSeconds += run->session->lastStepSeconds();
      ++run->steps;
      ++run->frameSteps;
    }
    return;
  }
  if (recordedFrame_ + 1 >= recordedFrames())
    throw Error(recorded_.front().path().string(), 0,
                "has no frame after frame " + std::to_string(recordedFrame_));
  ++recordedFrame_;
  for (std::size_t r = 0; r < runs_.size(); ++r)
    runs_[r]->recordedState = recorded_[r].read(recordedFrame_, runs_[r]->rest,
                                                "level " + std::to_string(runs_[r]->level));
}

Points3 LevelComparison::currentPositions(std::size_t r) const {
  const Run& run = *runs_[r];
  const Points3 level = run.session ? run.session->state().positions : run.recordedState.positions;
  return datasetPositions(*run.dataset, run.datasetLevel, level,
                          "level " + std::to_string(run.level));
}

const ComparedFrame& LevelComparison::compare() {
  ComparedFrame frame;
  frame.time = simulated() ? runs_.front()->session->simulation().time()
                           : recorded_.front().time(recordedFrame_);
  frame.steps = runs_.front()->steps;  // (every run takes each step)
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    Run& run = *runs_[r];
    DeformedState& deformed = *run.bound.deformed;
    run.deformer->deform(currentPositions(r), deformed.positions, deformed.normals);
    if (run.session) {
      const SimulationSession& session = *run.session;
      deformed.scalars = session.surfaceFields(session.simulation().frameFields(session.state()),
                                               run.bound.binding);
    } else {
      deformed.scalars = skinFields(
          run.rest, run.dataset->levels[static_cast<std::size_t>(run.datasetLevel)].firstNode,
          run.bound.binding, run.recordedState.vonMisesStress, run.recordedState.equivalentStrain);
    }
    frame.stepSeconds.push_back(
        run.frameSteps > 0 ? run.frameStepSeconds / static_cast<double>(run.frameSteps) : 0.0);
    run.frameStepSeconds = 0;
    run.frameSteps = 0;
  }
  const DeformedState& reference = *runs_[reference_]->bound.deformed;
  for (const auto& run : runs_) {
    DeformedState& deformed = *run->bound.deformed;
    surfaceErrors(deformed.positions, deformed.normals, reference.positions, reference.normals,
                  run->errors);
    deformed.scalars.push_back({arrays::kSurfaceError, run->errors.distance});
    deformed.scalars.push_back(
        {arrays::kRelativeError, run->errors.distance / (diagonal_ > 0 ? diagonal_ : 1.0)});
    deformed.scalars.push_back({arrays::kNormalAngle, run->errors.normalAngle});
    run->distances.insert(run->distances.end(), run->errors.distance.begin(),
                          run->errors.distance.end());
    run->angles.insert(run->angles.end(), run->errors.normalAngle.begin(),
                       run->errors.normalAngle.end());
    frame.errors.push_back(
        {spreadOfValues(run->errors.distance), spreadOfValues(run->errors.normalAngle)});
  }
  if (recorder_) {
    std::vector<const BoundSurface*> surfaces;
    for (const auto& run : runs_) surfaces.push_back(&run->bound);
    recorder_->addSurfacesFrame(frame.time, surfaces);
  }
  frames_.push_back(std::move(frame));
  return frames_.back();
}

const BoundSurface& LevelComparison::surface(std::size_t run) const {
  return runs_.at(run)->bound;
}

const SurfaceErrors& LevelComparison::errors(std::size_t run) const {
  return runs_.at(run)->errors;
}

ErrorSpread LevelComparison::overall(std::size_t run) const {
  const Run& r = *runs_.at(run);
  return {spreadOfFloats(r.distances), spreadOfFloats(r.angles)};
}

std::span<const float> LevelComparison::bodyValues(const std::vector<float>& values,
                                                   std::size_t frame, std::size_t body) const {
  const BodyRange& range = bodies_.at(body);
  return std::span<const float>(values).subspan(
      frame * static_cast<std::size_t>(surface_.vertexCount()) +
          static_cast<std::size_t>(range.firstVertex),
      static_cast<std::size_t>(range.vertexCount));
}

ErrorSpread LevelComparison::overall(std::size_t run, std::size_t body) const {
  const Run& r = *runs_.at(run);
  std::vector<float> distances, angles;
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    const std::span<const float> d = bodyValues(r.distances, f, body),
                                 a = bodyValues(r.angles, f, body);
    distances.insert(distances.end(), d.begin(), d.end());
    angles.insert(angles.end(), a.begin(), a.end());
  }
  return {spreadOfFloats(distances), spreadOfFloats(angles)};
}

ErrorSpread LevelComparison::frameErrors(std::size_t frame, std::size_t run,
                                         std::size_t body) const {
  const Run& r = *runs_.at(run);
  return {spreadOfFloats(bodyValues(r.distances, frame, body)),
          spreadOfFloats(bodyValues(r.angles, frame, body))};
}

double LevelComparison::meanStepSeconds(std::size_t run) const {
  const Run& r = *runs_.at(run);
  return r.steps > 0 ? r.stepSeconds / static_cast<double>(r.steps) : 0.0;
}

void LevelComparison::writeFrameTable(const std::filesystem::path& csv) const {
  const bool perBody = bodies_.size() > 1;
  writeTextAtomically(csv, [&](std::ostream& out) {
    out << "frame,time,run,level,step_ms,distance_max,distance_p99,distance_median,"
           "relative_max,relative_p99,relative_median,angle_max,angle_p99,angle_median"
        << (perBody ? ",body\n" : "\n");
    char row[512];
    const auto write = [&](std::size_t f, std::size_t r, const ErrorSpread& e, double diagonal) {
      if (diagonal <= 0) diagonal = 1;
      std::snprintf(
          row, sizeof row, "%zu,%.9g,%zu,%d,%.6g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6g,%.6g,%.6g", f,
          frames_[f].time, r, runs_[r]->level, 1e3 * frames_[f].stepSeconds[r], e.distance.max,
          e.distance.p99, e.distance.median, e.distance.max / diagonal, e.distance.p99 / diagonal,
          e.distance.median / diagonal, e.angle.max, e.angle.p99, e.angle.median);
      out << row;
    };
    for (std::size_t f = 0; f < frames_.size(); ++f)
      for (std::size_t r = 0; r < runs_.size(); ++r) {
        if (!perBody) {
          write(f, r, frames_[f].errors[r], diagonal_);
          out << "\n";
          continue;
        }
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
          write(f, r, frameErrors(f, r, b), bodyDiagonals_[b]);
          out << "," << b << "\n";
        }
      }
  });
}

}  // namespace tetskin
