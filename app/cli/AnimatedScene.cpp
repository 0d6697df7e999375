// SPDX-License-Identifier: AGPL-3.0-or-later
#include "AnimatedScene.h"

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkRenderer.h>

#include <chrono>

#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin::cli {
namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

AnimatedScene::AnimatedScene(const Dataset& dataset, const SurfaceInput& input,
                             const SceneOptions& o)
    : dataset_(dataset),
      level_(commandLevel(input, dataset.mesh, o.level, false)),
      nodes_(dataset.mesh.nodes),
      skin_(input.surface),
      skinBinding_(bindingAt(input, dataset.mesh, level_)) {
  // An unknown scenario or bad parameters fail now, before any frames.
  RunRequest run = o.run;
  run.level = level_;
  spec_ = resolveRun(run, dataset.mesh, dataset.config);
  makeScenario(spec_.scenario, spec_.parameters);
  surface_ = std::make_unique<DeformableSurface>(dataset.mesh, skin_, skinBinding_, o.path,
                                                 dataset.config.material, o.texture, o.fur);
  view_ = std::make_unique<OffscreenView>(o.width, o.height);
  surface_->addTo(view_->renderer());
  const TetMesh rest = extractLevel(dataset.mesh, level_);
  if (const auto style = fromName<ControlMeshStyle>(o.control); style != ControlMeshStyle::None) {
    control_ = std::make_unique<ControlMeshActor>(rest, style);
    view_->renderer()->AddActor(control_->actor());
  }
  // Framed on the control level at rest and the obstacles at the start:
  // the same view for every path.
  restBox_ = boundingBox(rest.nodes);
  for (const Obstacle& obstacle : spec_.options.obstacles) {
    auto actor = std::make_unique<ObstacleActor>(obstacle.shape->surface());
    view_->renderer()->AddActor(actor->actor());
    obstacles_.push_back(std::move(actor));
  }
  poseObstacles(0);
  for (const auto& actor : obstacles_) {
    const BoundingBox box = actor->bounds();
    restBox_.extend(box.min);
    restBox_.extend(box.max);
  }
  camera_ = o.camera;
  up_ = o.up;
  frame(restBox_);
  // The run's floor, a still's too (a scene's floor is part of the scene).
  if (const auto floor = spec_.options.floor()) showFloor(*floor);
  {
    // A gpu path that cannot draw here also reports it as a VTK error: the
    // command says it once, as its own error line.
    const VtkErrorCapture once(surface_->actor()->GetMapper());
    view_->render();
  }
  // The surface does not change size later: what fits now fits every frame.
  if (const std::string problem = surface_->gpuProblem(); !problem.empty()) throw Error(problem);
}

void AnimatedScene::frame(const BoundingBox& box) {
  BoundingBox all = restBox_;
  if (!box.empty()) {
    all.extend(box.min);
    all.extend(box.max);
  }
  const std::array<double, 6> bounds = toVtkBounds(all);
  view_->setCamera(camera_, bounds.data(), up_);
}

void AnimatedScene::poseObstacles(double time) {
  for (std::size_t k = 0; k < obstacles_.size(); ++k)
    obstacles_[k]->setPose(spec_.options.obstacles[k].poseAt(time).affine());
}

void AnimatedScene::startSimulation() {
  session_ = std::make_unique<SimulationSession>(dataset_.mesh, spec_);
  if (session_->contactNeedsSkin()) session_->bindSurface(skin_, skinBinding_, spec_.datasetName);
  surface_->setFrameSeconds(session_->options().timeStep);
  if (const auto floor = session_->options().floor()) showFloor(*floor);
  // The scenario's start may leave the rest shape's box (drop lifts it).
  frame(boundingBox(session_->state().positions));
}

void AnimatedScene::showFloor(const FloorPlane& floor) {
  if (floor_) view_->renderer()->RemoveActor(floor_->actor());
  floor_ = std::make_unique<FloorActor>(floor, restBox_);
  view_->renderer()->AddActor(floor_->actor());
}

AnimatedScene::~AnimatedScene() = default;

Index AnimatedScene::elementCount() const {
  return dataset_.mesh.levels[static_cast<std::size_t>(level_)].elementCount;
}

int AnimatedScene::furShells() const {
  return surface_->fur() ? surface_->fur()->shellsDrawn() : 0;
}

FrameTimes AnimatedScene::follow(const Points3& positions) {
  const LevelRange& range = dataset_.mesh.levels[static_cast<std::size_t>(level_)];
  nodes_.middleRows(range.firstNode, range.nodeCount) = positions;
  const FrameTimes times = surface_->update(nodes_);
  if (control_) control_->update(positions);
  return times;
}

void AnimatedScene::draw(const Points3& positions, double time, double seconds) {
  if (seconds > 0) surface_->setFrameSeconds(seconds);
  poseObstacles(time);
  follow(positions);
  view_->render();
}

FrameStats AnimatedScene::run(int frames, const std::function<void()>& afterDraw) {
  FrameStats s;
  s.frames = frames;
  if (frames > 0 && !session_) startSimulation();
  double outside = 0;  // seconds in afterDraw
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    auto t = std::chrono::steady_clock::now();
    session_->step();
    s.simulation += since(t);
    poseObstacles(session_->simulation().time());
    const FrameTimes times = follow(session_->state().positions);
    s.deformation += times.deformSeconds;
    s.upload += times.uploadSeconds;
    t = std::chrono::steady_clock::now();
    view_->render();
    s.draw += since(t);
    if (afterDraw) {
      t = std::chrono::steady_clock::now();
      afterDraw();
      outside += since(t);
    }
  }
  s.seconds = since(start) - outside;
  return s;
}

}  // namespace tetskin::cli
