// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Scene.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3D.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropPicker.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <cmath>
#include <cstdio>

#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/simulation/Prolongation.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::gui {
namespace {

const char* arrayName(ColorBy c) {
  switch (c) {
    case ColorBy::MinBarycentric:
      return arrays::kMinBarycentric;
    case ColorBy::Distance:
      return arrays::kDistance;
    case ColorBy::FaceId:
      return arrays::kFaceId;
    case ColorBy::VonMisesStress:
      return arrays::kVonMisesStress;
    case ColorBy::EquivalentStrain:
      return arrays::kEquivalentStrain;
    case ColorBy::Penetration:
      return arrays::kPenetration;
    case ColorBy::ContactForce:
      return arrays::kContactForce;
    case ColorBy::Material:
      break;
  }
  return "";
}

bool bySimulation(ColorBy c) {
  return c == ColorBy::VonMisesStress || c == ColorBy::EquivalentStrain;
}

bool byContact(ColorBy c) {
  return c == ColorBy::Penetration || c == ColorBy::ContactForce;
}

// Blue (0) to red (`maxValue`), as a legend shows it.
vtkSmartPointer<vtkLookupTable> zeroToMax(double maxValue) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.66, 0.0);
  lut->SetTableRange(0, std::max(maxValue, 1e-30));
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkActor> overlayActor(double r, double g, double b, float pointSize) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->PickableOff();
  vtkProperty* p = actor->GetProperty();
  p->SetColor(r, g, b);
  p->SetPointSize(pointSize);
  p->RenderPointsAsSpheresOn();
  p->SetLineWidth(3);
  p->LightingOff();
  actor->VisibilityOff();
  return actor;
}

}  // namespace

Scene::Scene(vtkRenderer* renderer) : renderer_(renderer) {
  styleBackground(renderer_);
  problems_ = overlayActor(1.0, 0.15, 0.1, 7);
  triangle_ = overlayActor(1.0, 0.85, 0.1, 11);
  prescribed_ = overlayActor(0.15, 0.45, 1.0, 8);
  renderer_->AddActor(problems_);
  renderer_->AddActor(triangle_);
  renderer_->AddActor(prescribed_);
  // The surface loads' arrows, orange: glyphs of an arrow along each
  // node's force (setLoadArrows).
  auto arrow = vtkSmartPointer<vtkArrowSource>::New();
  arrow->SetTipResolution(12);
  arrow->SetShaftResolution(12);
  loadGlyphs_ = vtkSmartPointer<vtkGlyph3D>::New();
  loadGlyphs_->SetSourceConnection(arrow->GetOutputPort());
  loadGlyphs_->SetVectorModeToUseVector();
  loadGlyphs_->SetScaleModeToScaleByVector();
  loadGlyphs_->OrientOn();
  auto glyphMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  glyphMapper->SetInputConnection(loadGlyphs_->GetOutputPort());
  glyphMapper->ScalarVisibilityOff();
  loadArrows_ = vtkSmartPointer<vtkActor>::New();
  loadArrows_->SetMapper(glyphMapper);
  loadArrows_->GetProperty()->SetColor(1.0, 0.55, 0.1);
  loadArrows_->VisibilityOff();
  renderer_->AddActor(loadArrows_);
  legend_ = vtkSmartPointer<vtkScalarBarActor>::New();
  legend_->SetNumberOfLabels(5);
  legend_->SetWidth(0.08);
  legend_->SetHeight(0.5);
  legend_->SetPosition(0.9, 0.25);
  legend_->VisibilityOff();
  renderer_->AddActor2D(legend_);
  overlay_ = vtkSmartPointer<vtkTextActor>::New();
  overlay_->GetTextProperty()->SetFontSize(14);
  overlay_->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  overlay_->SetDisplayPosition(8, 8);
  renderer_->AddActor2D(overlay_);
}

Scene::~Scene() = default;

void Scene::openDataset(const std::filesystem::path& path) {
  Dataset loaded = loadDataset(path);  // throws before anything changes
  std::optional<SurfaceMesh> surface = surface_;
  if (!surface && loaded.config.surface) {
    const std::filesystem::path file = loaded.config.resolve(*loaded.config.surface);
    if (std::filesystem::exists(file)) surface = readSurface(file);
  }
  const int level = loaded.mesh.finestLevel();
  SurfaceBinding binding;
  std::unique_ptr<DeformableSurface> drawing;
  if (surface) {
    binding = bindSurface(*surface, loaded.mesh, level);
    drawing = makeDrawing(loaded, *surface, binding, path_, loaded.config.fur);
  }
  install(std::move(loaded), path, std::move(surface), std::move(binding), level,
          std::move(drawing), {});
}

void Scene::openScene(const SceneRun& run) {
  Dataset loaded = run.dataset;
  if (run.request.up) loaded.config.up = *run.request.up;
  std::optional<SurfaceMesh> surface;
  SurfaceBinding binding;
  std::unique_ptr<DeformableSurface> drawing;
  if (run.surface) {
    surface = run.surface->surface;
    binding = run.surface->binding;
    drawing = makeDrawing(loaded, *surface, binding, path_, loaded.config.fur);
  }
  // (The dataset as the scene names it: several bodies' union by the scene.)
  install(std::move(loaded), run.request.datasetName, std::move(surface), std::move(binding),
          run.level, std::move(drawing), run.request.settings.obstacles);
}

void Scene::install(Dataset dataset, const std::filesystem::path& path,
                    std::optional<SurfaceMesh> surface, SurfaceBinding binding, int level,
                    std::unique_ptr<DeformableSurface> drawing, std::vector<Obstacle> obstacles) {
  dataset_ = std::move(dataset);
  datasetPath_ = path;
  surface_ = std::move(surface);
  binding_ = std::move(binding);
  fur_ = dataset_->config.fur;
  level_ = controlLevel_ = level;
  nodes_ = dataset_->mesh.nodes;
  setRunConditions({});  // (another body's)
  setLoadArrows({});
  previousSummary_.reset();
  picked_.reset();
  skinContact_ = {};
  setObstacles(std::move(obstacles));
  rebuildControl();
  showDrawing(std::move(drawing));
  setCamera(camera_);
}

void Scene::setObstacles(std::vector<Obstacle> obstacles) {
  for (const auto& actor : obstacleActors_) renderer_->RemoveActor(actor->actor());
  obstacleActors_.clear();
  obstacles_.clear();
  for (Obstacle& o : obstacles) addObstacle(std::move(o));
}

void Scene::addObstacle(Obstacle obstacle) {
  if (const auto problem = obstacleProblem(obstacle)) throw Error(*problem);
  auto actor = std::make_unique<ObstacleActor>(obstacle.shape->surface());
  actor->setPose(obstacle.poseAt(obstacleTime_).affine());
  renderer_->AddActor(actor->actor());
  obstacles_.push_back(std::move(obstacle));
  obstacleActors_.push_back(std::move(actor));
}

void Scene::setObstaclePlacement(std::size_t k, const ObstaclePose& placement) {
  obstacles_.at(k) = placedAt(obstacles_.at(k), placement);
  obstacleActors_[k]->setPose(obstacles_[k].poseAt(obstacleTime_).affine());
}

void Scene::poseObstacles(double time) {
  obstacleTime_ = time;
  for (std::size_t k = 0; k < obstacles_.size(); ++k)
    if (!obstacles_[k].motion.empty())
      obstacleActors_[k]->setPose(obstacles_[k].poseAt(time).affine());
}

void Scene::setSkinContact(SkinContact contact) {
  if (!surface_ || contact.penetration.size() != surface_->vertexCount()) contact = {};
  skinContact_ = std::move(contact);
  if (byContact(colorBy_)) applyColoring();
}

bool Scene::wantsSkinContact() const {
  return (!obstacles_.empty() || floor_) && surface_ && (byContact(colorBy_) || picked_);
}

void Scene::openSurface(const std::filesystem::path& path, SurfaceOrBinding read) {
  if (!dataset_)
    throw Error(path.string(), 0, "open a dataset before a surface (a binding's own dataset)");
  if (read.binding)
    checkBindingFits(*read.binding, read.surface.vertexCount(), dataset_->mesh, path.string());
  const bool bound = read.binding.has_value();
  SurfaceBinding binding =
      bound ? std::move(*read.binding) : bindSurface(read.surface, dataset_->mesh, level_);
  std::unique_ptr<DeformableSurface> drawing =
      makeDrawing(*dataset_, read.surface, binding, path_, fur_);
  surface_ = std::move(read.surface);
  binding_ = std::move(binding);
  if (bound) level_ = binding_.level;
  previousSummary_.reset();
  picked_.reset();
  showDrawing(std::move(drawing));
  if (bound) showControlAtBindingLevel();
  setCamera(camera_);  // (a surface placed elsewhere than the last would be out of view)
}

std::unique_ptr<DeformableSurface> Scene::makeDrawing(const Dataset& dataset,
                                                      const SurfaceMesh& surface,
                                                      const SurfaceBinding& binding,
                                                      RenderPath path,
                                                      const FurParameters& fur) const {
  std::filesystem::path texture;
  const DatasetConfig& config = dataset.config;
  if (surface.hasTexcoords()) {
    if (hasFur(path) && fur.colorTexture)
      texture = config.resolve(*fur.colorTexture);
    else if (config.texture)
      texture = config.resolve(*config.texture);
  }
  return std::make_unique<DeformableSurface>(dataset.mesh, surface, binding, path, config.material,
                                             texture, fur);
}

void Scene::rebuildSurface() {
  showDrawing(surface_ && dataset_ ? makeDrawing(*dataset_, *surface_, binding_, path_, fur_)
                                   : nullptr);
}

void Scene::showDrawing(std::unique_ptr<DeformableSurface> drawing) {
  if (surfaceDrawing_) {
    renderer_->RemoveActor(surfaceDrawing_->actor());
    if (FurLayer* fur = surfaceDrawing_->fur())
      for (vtkActor* a : fur->actors()) renderer_->RemoveActor(a);
  }
  surfaceDrawing_ = std::move(drawing);
  if (!surfaceDrawing_) return;
  surfaceDrawing_->addTo(renderer_);
  surfaceDrawing_->update(nodes_);
  deformer_ = std::make_unique<SurfaceDeformer>(*surface_, binding_, dataset_->mesh.nodes);
  deformedValid_ = false;
  const BoundingBox box = boundingBox(*surface_);
  summary_ = summarizeBinding(binding_, (box.max - box.min).norm());
  setSurfaceVisible(surfaceVisible_);
  applyColoring();
  updateDiagnostics();
}

void Scene::rebuildControl() {
  if (control_) renderer_->RemoveActor(control_->actor());
  control_.reset();
  controlTransfer_ = SparseMatrix();
  if (!dataset_) return;
  const TetMesh rest = extractLevel(dataset_->mesh, controlLevel_);
  if (controlLevel_ != level_)
    controlTransfer_ = nodalProlongation(extractLevel(dataset_->mesh, level_), rest.nodes);
  if (controlStyle_ == ControlMeshStyle::None) return;
  control_ = std::make_unique<ControlMeshActor>(rest, controlStyle_);
  control_->actor()->PickableOff();
  renderer_->AddActor(control_->actor());
  updateControlActor();
}

void Scene::updateControlActor() {
  if (!control_ || !dataset_) return;
  if (controlLevel_ != level_) {
    control_->update(shownControlPositions());
    return;
  }
  // The simulated level itself: its rows of nodes_, not copied.
  const LevelRange& r = dataset_->mesh.levels[static_cast<std::size_t>(level_)];
  control_->update(nodes_.middleRows(r.firstNode, r.nodeCount));
}

Points3 Scene::shownControlPositions() const {
  if (!dataset_) return Points3();
  const MultiLevelTetMesh& mesh = dataset_->mesh;
  const LevelRange& shown = mesh.levels[static_cast<std::size_t>(controlLevel_)];
  if (controlLevel_ == level_) return nodes_.middleRows(shown.firstNode, shown.nodeCount);
  const LevelRange& simulated = mesh.levels[static_cast<std::size_t>(level_)];
  const Points3 displacement = nodes_.middleRows(simulated.firstNode, simulated.nodeCount) -
                               mesh.nodes.middleRows(simulated.firstNode, simulated.nodeCount);
  return mesh.nodes.middleRows(shown.firstNode, shown.nodeCount) + controlTransfer_ * displacement;
}

void Scene::setRenderPath(RenderPath path) {
  std::unique_ptr<DeformableSurface> drawing =
      surface_ && dataset_ ? makeDrawing(*dataset_, *surface_, binding_, path, fur_) : nullptr;
  path_ = path;
  showDrawing(std::move(drawing));
}

void Scene::setFurParameters(const FurParameters& fur) {
  if (!hasFur(path_) || !surface_ || !dataset_) {
    fur_ = fur;
    return;
  }
  std::unique_ptr<DeformableSurface> drawing =
      makeDrawing(*dataset_, *surface_, binding_, path_, fur);
  fur_ = fur;
  showDrawing(std::move(drawing));
}

void Scene::setControlStyle(ControlMeshStyle style) {
  controlStyle_ = style;
  rebuildControl();
}

void Scene::setControlLevel(int level) {
  if (!dataset_) return;
  controlLevel_ = resolveLevel(dataset_->mesh, level);
  rebuildControl();
}

void Scene::setSurfaceVisible(bool visible) {
  surfaceVisible_ = visible;
  if (!surfaceDrawing_) return;
  surfaceDrawing_->actor()->SetVisibility(visible && !comparisonShown_);
  setFurVisible(furVisible_);
}

void Scene::setFurVisible(bool visible) {
  furVisible_ = visible;
  if (!surfaceDrawing_) return;
  if (FurLayer* fur = surfaceDrawing_->fur())
    for (vtkActor* a : fur->actors())
      a->SetVisibility(visible && surfaceVisible_ && !comparisonShown_);
}

void Scene::setColorBy(ColorBy colorBy) {
  colorBy_ = colorBy;
  applyColoring();
}

bool Scene::colorsBySimulation() const {
  return bySimulation(colorBy_);
}

void Scene::setSurfaceScalars(ColorBy colorBy, const Eigen::VectorXd& values) {
  if (colorBy != colorBy_ || !bySimulation(colorBy) || !surface_ ||
      values.size() != surface_->vertexCount())
    return;
  simulationScalars_ = values;
  applyColoring();
}

void Scene::showComparison(const SurfaceMesh& surface, const Eigen::VectorXd& values,
                           const std::string& title, double maxValue) {
  vtkSmartPointer<vtkPolyData> poly = toVtkPolyData(surface);
  poly->GetPointData()->SetScalars(toVtkScalars(title.c_str(), values));
  if (!comparison_) {
    comparison_ = vtkSmartPointer<vtkActor>::New();
    comparison_->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
    renderer_->AddActor(comparison_);
  }
  auto* mapper = vtkPolyDataMapper::SafeDownCast(comparison_->GetMapper());
  mapper->SetInputData(poly);
  const vtkSmartPointer<vtkLookupTable> lut = zeroToMax(maxValue);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(lut->GetTableRange());
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  comparison_->VisibilityOn();
  comparisonPositions_ = surface.positions;
  comparisonShown_ = true;
  setSurfaceVisible(surfaceVisible_);  // (hidden while the comparison is shown)
  legend_->SetLookupTable(lut);
  legend_->SetTitle(title.c_str());
  legend_->VisibilityOn();
}

void Scene::hideComparison() {
  if (!comparisonShown_) return;
  comparison_->VisibilityOff();
  comparisonShown_ = false;
  comparisonPositions_.resize(0, 3);
  setSurfaceVisible(surfaceVisible_);
  applyColoring();
}

std::optional<Index> Scene::pickComparisonVertex(int x, int y) {
  if (!comparisonShown_) return std::nullopt;
  auto picker = vtkSmartPointer<vtkPropPicker>::New();
  if (!picker->Pick(x, y, 0, renderer_) || picker->GetActor() != comparison_) return std::nullopt;
  const double* p = picker->GetPickPosition();
  const Index v = nearestPoint(comparisonPositions_, Eigen::Vector3d(p[0], p[1], p[2]));
  if (v < 0) return std::nullopt;
  return v;
}

void Scene::applyColoring() {
  if (comparisonShown_) return;  // (its legend stays)
  legend_->VisibilityOff();
  if (!surfaceDrawing_) return;
  vtkMapper* mapper = surfaceDrawing_->actor()->GetMapper();
  if (colorBy_ == ColorBy::Material) {
    mapper->ScalarVisibilityOff();
    return;
  }
  double range[2] = {0, 1};
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  switch (colorBy_) {
    case ColorBy::MinBarycentric:
      // Red below 0 (outside the triangle), blue inside.
      range[0] = std::min(-0.05, binding_.minBarycentric.minCoeff());
      range[1] = std::max(0.05, binding_.minBarycentric.maxCoeff());
      lut->SetHueRange(0.0, 0.66);
      break;
    case ColorBy::Distance: {
      const double m = std::max(1e-12, binding_.distance.cwiseAbs().maxCoeff());
      range[0] = -m;
      range[1] = m;
      lut->SetHueRange(0.66, 0.0);
      break;
    }
    case ColorBy::FaceId:
      range[1] = std::max(1, binding_.faceId.maxCoeff());
      lut->SetNumberOfTableValues(64);
      lut->SetHueRange(0.0, 1.0);
      break;
    case ColorBy::VonMisesStress:
    case ColorBy::EquivalentStrain: {
      // The frame's values (zero before the window sets any).
      const Index n = surface_ ? surface_->vertexCount() : 0;
      if (simulationScalars_.size() != n) simulationScalars_ = Eigen::VectorXd::Zero(n);
      vtkPolyData* poly = surfaceDrawing_->polyData();
      poly->GetPointData()->RemoveArray(arrays::kVonMisesStress);
      poly->GetPointData()->RemoveArray(arrays::kEquivalentStrain);
      poly->GetPointData()->AddArray(toVtkScalars(arrayName(colorBy_), simulationScalars_));
      range[1] =
          std::max(simulationScalars_.size() > 0 ? simulationScalars_.maxCoeff() : 0.0, 1e-30);
      lut->SetHueRange(0.66, 0.0);
      break;
    }
    case ColorBy::Penetration:
    case ColorBy::ContactForce: {
      // This frame's contact (zero before the run gives one): depth from
      // as far outside as the deepest vertex is inside (blue) to that
      // depth (red); the force's magnitude from 0.
      const Index n = surface_ ? surface_->vertexCount() : 0;
      Eigen::VectorXd values = Eigen::VectorXd::Zero(n);
      if (skinContact_.penetration.size() == n && n > 0)
        values = colorBy_ == ColorBy::Penetration ? skinContact_.penetration
                                                  : skinContact_.forces.rowwise().norm().eval();
      vtkPolyData* poly = surfaceDrawing_->polyData();
      poly->GetPointData()->RemoveArray(arrayName(colorBy_));
      poly->GetPointData()->AddArray(toVtkScalars(arrayName(colorBy_), values));
      const double top = std::max(n > 0 ? values.maxCoeff() : 0.0, 1e-30);
      range[0] = colorBy_ == ColorBy::Penetration ? -top : 0;
      range[1] = top;
      lut->SetHueRange(0.66, 0.0);
      break;
    }
    case ColorBy::Material:
      break;
  }
  lut->SetTableRange(range);
  lut->Build();
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(arrayName(colorBy_));
  mapper->SetScalarRange(range);
  mapper->SetColorModeToMapScalars();
  mapper->ScalarVisibilityOn();
  legend_->SetLookupTable(lut);
  legend_->SetTitle(arrayName(colorBy_));
  legend_->VisibilityOn();
}

void Scene::setHighlightProblems(bool on) {
  highlight_ = on;
  updateDiagnostics();
}

void Scene::setFloor(const std::optional<FloorPlane>& floor) {
  if (floor && floor_ && *floor == floorPlane_ && floorLevel_ == level_) return;
  if (floor_) renderer_->RemoveActor(floor_->actor());
  floor_.reset();
  if (!floor || !dataset_) return;
  floor_ =
      std::make_unique<FloorActor>(*floor, boundingBox(extractLevel(dataset_->mesh, level_).nodes));
  floor_->actor()->PickableOff();
  renderer_->AddActor(floor_->actor());
  floorPlane_ = *floor;
  floorLevel_ = level_;
}

void Scene::setRunConditions(const RunConditions& conditions) {
  setFloor(conditions.floor);
  if (conditions.prescribedNodes == prescribedNodes_) return;  // (each frame shown sets them)
  prescribedNodes_ = conditions.prescribedNodes;
  updatePrescribedMarks();
}

void Scene::setLoadArrows(const Points3& forces) {
  loadArrowCount_ = 0;
  const double largest = forces.rows() > 0 ? forces.rowwise().norm().maxCoeff() : 0.0;
  if (!dataset_ || !(largest > 0) || !std::isfinite(largest)) {
    loadArrows_->VisibilityOff();
    return;
  }
  const LevelRange& r = dataset_->mesh.levels[static_cast<std::size_t>(level_)];
  const double scale = 0.1 * restBox().diagonal() / largest;  // metres per newton
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto vectors = vtkSmartPointer<vtkDoubleArray>::New();
  vectors->SetNumberOfComponents(3);
  vectors->SetName("LoadForce");
  for (Index node = 0; node < std::min<Index>(forces.rows(), r.nodeCount); ++node) {
    const Eigen::Vector3d f = forces.row(node).transpose();
    if (f.squaredNorm() == 0) continue;
    // The arrow's tail: it ends on the node, pushing it.
    const Eigen::Vector3d tail = nodes_.row(r.firstNode + node).transpose() - scale * f;
    points->InsertNextPoint(tail.data());
    vectors->InsertNextTuple(f.data());
    ++loadArrowCount_;
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->GetPointData()->SetVectors(vectors);
  loadGlyphs_->SetInputData(poly);
  loadGlyphs_->SetScaleFactor(scale);
  loadArrows_->SetVisibility(loadArrowCount_ > 0);
}

void Scene::setPrescribedNodesShown(bool shown) {
  prescribedShown_ = shown;
  updatePrescribedMarks();
}

void Scene::updatePrescribedMarks() {
  markedPrescribed_ = 0;
  if (prescribedShown_ && dataset_) {
    const LevelRange& r = dataset_->mesh.levels[static_cast<std::size_t>(level_)];
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    for (int node : prescribedNodes_) {
      if (node < 0 || node >= r.nodeCount) continue;  // (of a level no longer bound)
      const Eigen::Vector3d p = nodes_.row(r.firstNode + node).transpose();
      const vtkIdType id = points->InsertNextPoint(p.data());
      verts->InsertNextCell(1, &id);
      ++markedPrescribed_;
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);
    vtkPolyDataMapper::SafeDownCast(prescribed_->GetMapper())->SetInputData(poly);
  }
  prescribed_->SetVisibility(markedPrescribed_ > 0);
}

std::optional<FloorPlane> Scene::floor() const {
  if (!floor_) return std::nullopt;
  return floorPlane_;
}

BoundingBox Scene::restBox() const {
  BoundingBox box =
      surface_ ? boundingBox(*surface_) : boundingBox(extractLevel(dataset_->mesh, level_).nodes);
  for (const auto& actor : obstacleActors_) {
    box.extend(actor->bounds().min);
    box.extend(actor->bounds().max);
  }
  return box;
}

void Scene::setCamera(CameraPreset preset) {
  camera_ = preset;
  if (!dataset_) return;
  const BoundingBox box = restBox();
  const std::array<double, 6> bounds = toVtkBounds(box);
  placeCamera(renderer_, preset, bounds.data(), dataset_->config.up);
}

void Scene::keepInView(const BoundingBox& box) {
  if (!dataset_ || box.empty()) return;
  const std::array<double, 6> start = toVtkBounds(box);
  if (boundsInView(renderer_, start.data())) return;
  BoundingBox both = restBox();
  both.extend(box.min);
  both.extend(box.max);
  std::array<double, 6> bounds = toVtkBounds(both);
  renderer_->ResetCamera(bounds.data());  // (its direction and up kept)
}

void Scene::setUpAxis(UpAxis up) {
  if (!dataset_) return;
  dataset_->config.up = up;
  setCamera(camera_);
}

void Scene::setOverlayText(const std::string& text) {
  overlay_->SetInput(text.c_str());
}

void Scene::rebind(BindingMethod method, int level) {
  if (!dataset_ || !surface_) throw Error("open a dataset and a surface first");
  const int resolved = resolveLevel(dataset_->mesh, level);
  BindingOptions options;
  options.method = method;
  SurfaceBinding binding = bindSurface(*surface_, dataset_->mesh, resolved, options);
  std::unique_ptr<DeformableSurface> drawing =
      makeDrawing(*dataset_, *surface_, binding, path_, fur_);
  previousSummary_ = summary_;
  binding_ = std::move(binding);
  level_ = resolved;
  picked_.reset();
  showDrawing(std::move(drawing));
  showControlAtBindingLevel();
}

void Scene::showControlAtBindingLevel() {
  if (controlLevel_ == level_) return;
  controlLevel_ = level_;
  rebuildControl();
}

std::string Scene::comparisonText() const {
  auto line = [](const BindingSummary& s) {
    char text[160];
    std::snprintf(text, sizeof text, "inside %.1f%%, |d| p50 %.2e p99 %.2e max %.2e",
                  100 * s.shareInside, s.distanceP50, s.distanceP99, s.distanceMax);
    return std::string(text);
  };
  std::string out = "now:    " + line(summary_);
  if (previousSummary_) out += "\nbefore: " + line(*previousSummary_);
  if (const std::string warning = misfitWarning(); !warning.empty()) out += "\nwarning: " + warning;
  return out;
}

std::string Scene::misfitWarning() const {
  return tetskin::misfitWarning(summary_, dataset_->mesh, binding_.level);
}

VertexInfo Scene::vertexInfo(Index v) const {
  VertexInfo info;
  if (!surface_ || v < 0 || v >= surface_->vertexCount()) return info;
  info.vertex = v;
  info.face = binding_.faceId[v];
  info.controlIds = binding_.controlIds.row(v).transpose();
  info.weights = binding_.weights.row(v).transpose();
  info.distance = binding_.distance[v];
  info.minBarycentric = binding_.minBarycentric[v];
  info.position = deformedPositions().row(v).transpose();
  if (skinContact_.penetration.size() == surface_->vertexCount()) {
    info.penetration = skinContact_.penetration[v];
    info.contactForce = skinContact_.forces.row(v).transpose();
  }
  return info;
}

std::optional<Index> Scene::pickVertex(int x, int y) {
  if (!surfaceDrawing_ || !surfaceVisible_) return std::nullopt;
  auto picker = vtkSmartPointer<vtkPropPicker>::New();
  if (!picker->Pick(x, y, 0, renderer_) || picker->GetActor() != surfaceDrawing_->actor())
    return std::nullopt;
  const double* p = picker->GetPickPosition();
  const Index v = nearestPoint(deformedPositions(), Eigen::Vector3d(p[0], p[1], p[2]));
  if (v < 0) return std::nullopt;
  showPickedVertex(v);
  return v;
}

void Scene::showPickedVertex(std::optional<Index> vertex) {
  picked_ = vertex;
  updateDiagnostics();
}

Eigen::Vector3d Scene::displayToWorld(int x, int y, const Eigen::Vector3d& near) const {
  renderer_->SetWorldPoint(near.x(), near.y(), near.z(), 1.0);
  renderer_->WorldToDisplay();
  const double depth = renderer_->GetDisplayPoint()[2];
  renderer_->SetDisplayPoint(x, y, depth);
  renderer_->DisplayToWorld();
  const double* w = renderer_->GetWorldPoint();
  const double h = w[3] != 0 ? w[3] : 1.0;
  return Eigen::Vector3d(w[0] / h, w[1] / h, w[2] / h);
}

FrameTimes Scene::showControlState(const Points3& levelPositions) {
  FrameTimes times;
  if (!dataset_) return times;
  const LevelRange& r = dataset_->mesh.levels[static_cast<std::size_t>(level_)];
  if (levelPositions.rows() != r.nodeCount) return times;
  nodes_.middleRows(r.firstNode, r.nodeCount) = levelPositions;
  deformedValid_ = false;
  if (surfaceDrawing_) times = surfaceDrawing_->update(nodes_);
  updateControlActor();
  updateDiagnostics();
  updatePrescribedMarks();
  return times;
}

const Points3& Scene::deformedPositions() const {
  if (!deformedValid_ && deformer_) {
    deformer_->deform(nodes_, deformed_, deformedNormals_);
    deformedValid_ = true;
  }
  return deformed_;
}

vtkActor* Scene::surfaceActor() const {
  return surfaceDrawing_ ? surfaceDrawing_->actor() : nullptr;
}

void Scene::updateDiagnostics() {
  // Problem vertices.
  highlighted_ = 0;
  if (highlight_ && surface_) {
    const Points3& x = deformedPositions();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    const double far = summary_.distanceP99 * summary_.diagonal;
    for (Index v = 0; v < x.rows(); ++v)
      if (binding_.minBarycentric[v] < 0 || std::abs(binding_.distance[v]) > far) {
        const vtkIdType id = points->InsertNextPoint(x(v, 0), x(v, 1), x(v, 2));
        verts->InsertNextCell(1, &id);
        ++highlighted_;
      }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);
    vtkPolyDataMapper::SafeDownCast(problems_->GetMapper())->SetInputData(poly);
  }
  problems_->SetVisibility(highlight_ && highlighted_ > 0);
  // The picked vertex, its control triangle (or tetrahedron) and their link.
  if (picked_ && surface_) {
    const VertexInfo info = vertexInfo(*picked_);
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    const int n = binding_.controlsPerVertex();
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d p = nodes_.row(info.controlIds[k]).transpose();
      anchor += info.weights[k] * p;
      const vtkIdType id = points->InsertNextPoint(p.data());
      verts->InsertNextCell(1, &id);
    }
    for (int k = 0; k < n; ++k)
      for (int j = k + 1; j < n; ++j) {
        const vtkIdType edge[2] = {k, j};
        lines->InsertNextCell(2, edge);
      }
    const vtkIdType a = points->InsertNextPoint(anchor.data());
    const vtkIdType b = points->InsertNextPoint(info.position.data());
    const vtkIdType link[2] = {a, b};
    lines->InsertNextCell(2, link);
    verts->InsertNextCell(1, &b);
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);
    poly->SetLines(lines);
    vtkPolyDataMapper::SafeDownCast(triangle_->GetMapper())->SetInputData(poly);
  }
  triangle_->SetVisibility(picked_.has_value() && surface_.has_value());
}

BoundSurface Scene::deformedBoundSurface() const {
  if (!surface_) throw Error("no surface to export");
  return BoundSurface{*surface_, binding_, datasetPath_.generic_string(),
                      DeformedState{deformedPositions(), deformedNormals_}};
}

}  // namespace tetskin::gui
