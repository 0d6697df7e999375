// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What tetskin-gui shows, without any Qt widget: the dataset, the bound
// surface drawn by a render path (with fur on the fur paths), the control
// mesh of a chosen level, binding diagnostics (colour by an array with a
// legend, problem vertices, the picked vertex's control triangle) and the
// FPS overlay. It only wires the modules' public APIs; MainWindow drives it
// and the tests drive it through MainWindow.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/binding/BindingSummary.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/RunConditions.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/rendering/ControlMeshActor.h"
#include "tetskin/rendering/DeformableSurface.h"
#include "tetskin/rendering/FloorActor.h"
#include "tetskin/rendering/ObstacleActor.h"
#include "tetskin/rendering/OffscreenView.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/simulation/CorotatedFem.h"
#include "tetskin/simulation/Obstacle.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/vtkio/BindingFile.h"

class vtkActor;
class vtkGlyph3D;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

namespace tetskin::gui {
// What colours the surface: its material, a binding array, the simulated
// level's stress or strain carried to the skin (SurfaceFields.h), or the
// skin's contact with the obstacles (its penetration, its contact force's
// magnitude).
enum class ColorBy {
  Material,
  MinBarycentric,
  Distance,
  FaceId,
  VonMisesStress,
  EquivalentStrain,
  Penetration,
  ContactForce
};
}  // namespace tetskin::gui

template <>
struct tetskin::EnumSchema<tetskin::gui::ColorBy> {
  static constexpr const char* what = "colouring";
  static constexpr EnumValue<gui::ColorBy> values[] = {
      {gui::ColorBy::Material, "material", ""},
      {gui::ColorBy::MinBarycentric, arrays::kMinBarycentric, ""},
      {gui::ColorBy::Distance, arrays::kDistance, ""},
      {gui::ColorBy::FaceId, arrays::kFaceId, ""},
      {gui::ColorBy::VonMisesStress, arrays::kVonMisesStress, ""},
      {gui::ColorBy::EquivalentStrain, arrays::kEquivalentStrain, ""},
      {gui::ColorBy::Penetration, arrays::kPenetration, ""},
      {gui::ColorBy::ContactForce, arrays::kContactForce, ""}};
};

namespace tetskin::gui {

struct VertexInfo {
  Index vertex = -1;
  int face = -1;               // its FaceId: the element it is bound to
  Eigen::Vector4i controlIds;  // dataset numbering; 4th is -1 for triangle bindings
  Eigen::Vector4d weights;
  double distance = 0, minBarycentric = 0;
  Eigen::Vector3d position;  // deformed, this frame
  // Its contact this frame, where the run has obstacles (Scene::
  // setSkinContact): depth inside the obstacle it is deepest in (negative
  // outside) and its contact spring's force.
  std::optional<double> penetration;
  Eigen::Vector3d contactForce = Eigen::Vector3d::Zero();
};

class Scene {
 public:
  explicit Scene(vtkRenderer* renderer);
  ~Scene();

  // Loading; each throws Error naming the file (and line) on bad input and
  // leaves the scene as it was.
  void openDataset(const std::filesystem::path& path);  // .json, .node or .ele
  // OBJ, PLY, STL or VTP, bound at once to the current level; a .vtp from
  // tetskin bind with its own binding (and level) as it is.
  // A surface or binding read from `path` (readSurfaceOrBinding, BindingFile.h):
  // a binding is checked against the open dataset, a surface bound to it.
  void openSurface(const std::filesystem::path& path, SurfaceOrBinding read);
  // A scene made ready (SceneRun.h): its placed dataset (named by the
  // body's dataset path), its surface and binding, its level and its
  // obstacles, which replace those shown.
  void openScene(const SceneRun& run);
  bool hasDataset() const { return dataset_.has_value(); }
  bool hasSurface() const { return surface_.has_value(); }
  const Dataset& dataset() const { return *dataset_; }
  const std::filesystem::path& datasetPath() const { return datasetPath_; }
  const SurfaceMesh& surface() const { return *surface_; }
  const SurfaceBinding& binding() const { return binding_; }
  // The bound (and simulated) level.
  int level() const { return level_; }

  // View.
  void setRenderPath(RenderPath path);
  RenderPath renderPath() const { return path_; }
  void setFurParameters(const FurParameters& fur);
  void setControlStyle(ControlMeshStyle style);
  ControlMeshStyle controlStyle() const { return controlStyle_; }
  // The shown control level. Another level than level() follows the
  // simulated one: each of its nodes moves with the simulated level's
  // displacement interpolated at its rest position (barycentric in the
  // simulated level's tetrahedra, as the multigrid's transfer operators).
  void setControlLevel(int level);
  int controlLevel() const { return controlLevel_; }
  // The shown control level's node positions this frame (level-local).
  Points3 shownControlPositions() const;
  void setSurfaceVisible(bool visible);
  bool surfaceVisible() const { return surfaceVisible_; }
  // The fur of the fur paths on its own (the skin stays).
  void setFurVisible(bool visible);
  bool furVisible() const { return furVisible_; }
  void setColorBy(ColorBy colorBy);
  ColorBy colorBy() const { return colorBy_; }
  // Whether the colouring is by a value of the simulation's frame (stress,
  // strain), which the window sets each frame it shows (setSurfaceScalars).
  bool colorsBySimulation() const;
  // The bound surface's values of `colorBy` (VonMisesStress or
  // EquivalentStrain) this frame, one per vertex; ignored for a surface of
  // another size.
  void setSurfaceScalars(ColorBy colorBy, const Eigen::VectorXd& values);

  // A comparison of levels (CompareDock): `surface` (a level's deformation
  // of the bound surface, with normals) drawn in place of the bound surface
  // and its fur, coloured by `values` from 0 (blue) to `maxValue` (red)
  // under the legend `title`, until hideComparison().
  void showComparison(const SurfaceMesh& surface, const Eigen::VectorXd& values,
                      const std::string& title, double maxValue);
  void hideComparison();
  bool comparisonShown() const { return comparisonShown_; }
  // The comparison's vertex nearest the surface point under display (x, y);
  // nullopt off it.
  std::optional<Index> pickComparisonVertex(int x, int y);
  // Marks vertices with a negative weight or a distance beyond the 99th percentile.
  void setHighlightProblems(bool on);
  Index highlightedCount() const { return highlighted_; }
  // Frames the surface (else the control level) from the preset's side; a
  // dataset or surface opened later is framed from the same side.
  void setCamera(CameraPreset preset);
  // Moves the camera back, keeping its direction and up, until `box` (a
  // simulation's start, such as a drop's lifted body) is in view with the
  // surface (else the control level); a camera that shows it already stays.
  void keepInView(const BoundingBox& box);
  // The dataset's up axis from now on (its config in memory; the file is
  // not changed): the camera is placed again from the same side.
  void setUpAxis(UpAxis up);
  void setOverlayText(const std::string& text);

  // Obstacles: drawn translucent, as the next run meets them (a scene's,
  // those added, as placed). Opening a dataset clears them, a scene
  // replaces them.
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  // Throws Error (obstacleProblem) for an obstacle the run would refuse.
  void addObstacle(Obstacle obstacle);
  void setObstaclePlacement(std::size_t k, const ObstaclePose& placement);
  // The obstacles drawn as posed at simulated time t (a moving one follows
  // its keyframes).
  void poseObstacles(double time);
  const ObstacleActor& obstacleActor(std::size_t k) const { return *obstacleActors_[k]; }
  // The skin's contact this frame (Simulation::skinContact; empty: none):
  // what colouring by Penetration or ContactForce shows, and the picked
  // vertex's contact state. Ignored for a skin of another size.
  void setSkinContact(SkinContact contact);
  // Whether the shown frame needs the skin's contact (a colouring by it,
  // or a picked vertex).
  bool wantsSkinContact() const;

  // Binding diagnostics.
  void rebind(BindingMethod method, int level);
  const BindingSummary& summary() const { return summary_; }
  // The summary before the last rebind, for comparison.
  const std::optional<BindingSummary>& previousSummary() const { return previousSummary_; }
  std::string comparisonText() const;
  // The binding's misfitWarning (a surface far from its level), or empty.
  std::string misfitWarning() const;
  VertexInfo vertexInfo(Index vertex) const;
  // Hardware pick at display coordinates (VTK's: origin bottom left); the
  // nearest surface vertex to the picked point, and shows its control triangle.
  std::optional<Index> pickVertex(int x, int y);
  void showPickedVertex(std::optional<Index> vertex);
  std::optional<Index> pickedVertex() const { return picked_; }
  // World point under display (x, y) at the depth of `near` (for dragging).
  Eigen::Vector3d displayToWorld(int x, int y, const Eigen::Vector3d& near) const;

  // The conditions of the run shown: the simulation's, or a recorded run's
  // while it is shown. Its floor is drawn under the bound level at rest
  // (built again only when the plane or the level changes); its prescribed
  // nodes (of the bound level) are marked while setPrescribedNodesShown is on.
  void setRunConditions(const RunConditions& conditions);
  std::optional<FloorPlane> floor() const;
  const std::vector<int>& prescribedNodes() const { return prescribedNodes_; }
  void setPrescribedNodesShown(bool shown);
  bool prescribedNodesShown() const { return prescribedShown_; }
  // The nodes marked this frame (0 while the marks are off).
  Index markedPrescribedCount() const { return markedPrescribed_; }
  // Arrows at the nodes of the bound level where `forces` (level numbering,
  // N: the surface loads' consistent forces) act, each along its force and
  // ending at its node, the longest a tenth of the body's diagonal at rest;
  // none where a row is zero, and hidden for empty `forces`. Drawn at the
  // nodes' present positions: call after showControlState.
  void setLoadArrows(const Points3& forces);
  // The arrows drawn this frame.
  Index loadArrowCount() const { return loadArrowCount_; }
  // A simulated frame: the bound level's node positions (level-local).
  FrameTimes showControlState(const Points3& levelPositions);
  // The current state in the dataset's numbering, and the deformed surface.
  const Points3& controlNodes() const { return nodes_; }
  const Points3& deformedPositions() const;
  DeformableSurface* deformable() const { return surfaceDrawing_.get(); }
  vtkActor* surfaceActor() const;

  // The bound surface deformed to this frame (for .vtp export).
  BoundSurface deformedBoundSurface() const;

 private:
  // The drawing of `surface` bound by `binding` to `dataset` on `path` with
  // `fur` (and the dataset's texture where the surface has texture
  // coordinates). It changes nothing: a change to the dataset, surface,
  // binding, path or fur makes its drawing first and takes the new state on
  // after, so one that cannot be drawn (e.g. its texture file is gone)
  // throws with the scene as it was.
  // The box the camera presets frame: the surface's, else the bound level's
  // at rest, with the obstacles'.
  BoundingBox restBox() const;
  std::unique_ptr<DeformableSurface> makeDrawing(const Dataset& dataset, const SurfaceMesh& surface,
                                                 const SurfaceBinding& binding, RenderPath path,
                                                 const FurParameters& fur) const;
  // Puts `drawing` (of the scene's current state; null: none) in place of
  // the old one, with the deformer, summary and diagnostics that go with it.
  void showDrawing(std::unique_ptr<DeformableSurface> drawing);
  // showDrawing() of the current state's drawing (none without a surface).
  void rebuildSurface();
  void rebuildControl();
  // The control actor to the shown level's positions this frame.
  void updateControlActor();
  // The control mesh drawn at the binding's level (after a new binding).
  void showControlAtBindingLevel();
  void applyColoring();
  void updateDiagnostics();
  void updatePrescribedMarks();
  void setFloor(const std::optional<FloorPlane>& floor);
  // `dataset` (named `path`) with `surface` bound by `binding` at `level`
  // (and its drawing), in place of what is open; `obstacles` replace the
  // shown ones.
  void install(Dataset dataset, const std::filesystem::path& path,
               std::optional<SurfaceMesh> surface, SurfaceBinding binding, int level,
               std::unique_ptr<DeformableSurface> drawing, std::vector<Obstacle> obstacles);
  void setObstacles(std::vector<Obstacle> obstacles);

  vtkRenderer* renderer_;
  std::optional<Dataset> dataset_;
  std::filesystem::path datasetPath_;
  std::optional<SurfaceMesh> surface_;
  SurfaceBinding binding_;
  BindingSummary summary_;
  std::optional<BindingSummary> previousSummary_;
  int level_ = 0, controlLevel_ = 0;
  RenderPath path_ = RenderPath::Cpu;
  CameraPreset camera_ = CameraPreset::Iso;
  FurParameters fur_;
  ControlMeshStyle controlStyle_ = ControlMeshStyle::Wireframe;
  bool surfaceVisible_ = true, furVisible_ = true, highlight_ = false;
  ColorBy colorBy_ = ColorBy::Material;
  Index highlighted_ = 0;
  std::optional<Index> picked_;
  Points3 nodes_;  // dataset numbering, this frame
  mutable Points3 deformed_, deformedNormals_;
  mutable bool deformedValid_ = false;
  std::unique_ptr<SurfaceDeformer> deformer_;
  std::unique_ptr<DeformableSurface> surfaceDrawing_;
  std::unique_ptr<ControlMeshActor> control_;
  std::unique_ptr<FloorActor> floor_;
  FloorPlane floorPlane_;             // (with floor_)
  int floorLevel_ = -1;               // the level floor_ lies under
  std::vector<int> prescribedNodes_;  // the bound level's numbering
  bool prescribedShown_ = false;
  Index markedPrescribed_ = 0;
  // Shown level's nodes x simulated level's nodes (empty when they are one
  // level): nodalProlongation at the shown level's rest nodes.
  SparseMatrix controlTransfer_;
  vtkSmartPointer<vtkActor> problems_, triangle_, prescribed_, loadArrows_;
  vtkSmartPointer<vtkGlyph3D> loadGlyphs_;  // loadArrows_' input
  Index loadArrowCount_ = 0;
  // Stress or strain on the skin this frame (setSurfaceScalars), and the
  // comparison shown in place of the surface.
  Eigen::VectorXd simulationScalars_;
  vtkSmartPointer<vtkActor> comparison_;
  Points3 comparisonPositions_;
  bool comparisonShown_ = false;
  std::vector<Obstacle> obstacles_;
  std::vector<std::unique_ptr<ObstacleActor>> obstacleActors_;  // one per obstacle
  double obstacleTime_ = 0;                                     // posed at
  SkinContact skinContact_;                                     // this frame's (or empty)
  vtkSmartPointer<vtkScalarBarActor> legend_;
  vtkSmartPointer<vtkTextActor> overlay_;
};

}  // namespace tetskin::gui
