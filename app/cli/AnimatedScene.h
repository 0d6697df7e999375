// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The animated scene of `tetskin render --frames`, `render --run` and
// `tetskin bench`: a simulated or recorded control level, a bound surface
// drawn by one render path, the run's obstacles (posed at each frame's
// time) and floor, an offscreen view; run(N) times N simulated frames
// stage by stage, draw() shows a recorded state.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "ScenarioOptions.h"
#include "SurfaceInput.h"
#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/rendering/ControlMeshActor.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/rendering/FloorActor.h"
#include "tetskin/rendering/ObstacleActor.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/simulation/Scenario.h"

namespace tetskin::cli {

struct SceneOptions {
  int level = kFinestLevel;  // (a binding's own level, when the surface input is one)
  RenderPath path = kDefaultRenderPath;
  // The simulated frames' run (its level: the scene's); a step per frame.
  RunRequest run;
  // The image's size (render --size); the GUI's window starts larger
  // (1280x800, tetskin-gui --size): a window with docks, not an image.
  int width = 800, height = 600;
  CameraPreset camera = kDefaultCamera;
  UpAxis up = UpAxis::Y;  // of the camera presets and the simulation
  std::string control = toString(ControlMeshStyle::None);  // a ControlMeshStyle's name
  std::filesystem::path texture;  // PNG applied through the surface's texture coordinates
                                  // (on fur paths: the fur's colour and mask)
  FurParameters fur;              // for the fur paths
};

struct FrameStats {
  int frames = 0;
  double seconds = 0;                                            // wall time of all frames
  double simulation = 0, deformation = 0, upload = 0, draw = 0;  // summed
  double framesPerSecond() const { return seconds > 0 ? frames / seconds : 0; }
};

class AnimatedScene {
 public:
  // The input's binding is drawn as it is, on its level; a plain surface is
  // bound to options.level. The run's obstacles are drawn (framed with the
  // level at rest), and a simulated run binds the surface into its contact
  // where the contact needs a skin (SimulationSession::contactNeedsSkin).
  AnimatedScene(const Dataset& dataset, const SurfaceInput& surface, const SceneOptions& options);
  ~AnimatedScene();
  // Simulates, deforms and draws `frames` frames (the first draw, which
  // compiles shaders, happens in the constructor and is not counted). The
  // simulation is set up on the first frames run: a still image needs none
  // (nor a level the simulation would refuse).
  // `afterDraw`, if given, runs after each frame is drawn (render's film
  // takes the picture); its time is left out of the stats.
  FrameStats run(int frames, const std::function<void()>& afterDraw = {});
  // Seconds a simulated frame stands for (the time step).
  double frameSeconds() const { return spec_.options.timeStep; }
  // The simulated body's material.
  const ElasticMaterial& material() const { return spec_.options.material; }
  // Draws the control level at `positions` (a recorded frame's state, at
  // `time`: the obstacles' poses), `seconds` after the state drawn before
  // it (for the fur's drag).
  void draw(const Points3& positions, double time, double seconds);
  // Draws `floor` under the control level (at rest): a run with a floor,
  // such as a drop, is seen to land. The run's own floor, if it has one,
  // is drawn from the start (a still too).
  void showFloor(const FloorPlane& floor);
  // Frames the camera (the same preset) on `box` together with the control
  // level at rest: for a motion that leaves the rest shape's box, such as
  // a drop's lifted start.
  void frame(const BoundingBox& box);
  OffscreenView& view() { return *view_; }
  int level() const { return level_; }
  Index elementCount() const;
  // Shells the fur paths drew in the last frame (0 without fur).
  int furShells() const;

 private:
  const Dataset& dataset_;
  int level_;
  std::unique_ptr<DeformableSurface> surface_;
  std::unique_ptr<OffscreenView> view_;
  std::unique_ptr<ControlMeshActor> control_;
  std::unique_ptr<FloorActor> floor_;
  std::vector<std::unique_ptr<ObstacleActor>> obstacles_;  // spec_'s, in its order
  RunSpec spec_;                                           // the simulated frames' run
  UpAxis up_ = UpAxis::Y;
  CameraPreset camera_ = CameraPreset::Iso;
  BoundingBox restBox_;                         // of the control level at rest
  std::unique_ptr<SimulationSession> session_;  // from the first frames run on
  Points3 nodes_;
  SurfaceMesh skin_;  // as bound to the level
  SurfaceBinding skinBinding_;

  void startSimulation();
  // The obstacles as posed at `time`.
  void poseObstacles(double time);
  // The surface and control mesh follow the level's nodes at `positions`.
  FrameTimes follow(const Points3& positions);
};

}  // namespace tetskin::cli
