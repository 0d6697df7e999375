// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/BindingFile.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <utility>

#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/PartitionedSurface.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

template <typename Array, typename Matrix>
vtkSmartPointer<Array> columns(const char* name, const Matrix& m, int count) {
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfComponents(count);
  a->SetNumberOfTuples(m.rows());
  for (Index r = 0; r < m.rows(); ++r)
    for (int c = 0; c < count; ++c) a->SetTypedComponent(r, c, m(r, c));
  return a;
}

void addString(vtkFieldData* fd, const char* name, const std::string& value) {
  auto a = vtkSmartPointer<vtkStringArray>::New();
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

std::string getString(vtkFieldData* fd, const char* name, const std::string& source) {
  auto* a = vtkStringArray::SafeDownCast(fd ? fd->GetAbstractArray(name) : nullptr);
  if (!a || a->GetNumberOfValues() < 1)
    throw Error(source, 0,
                std::string("is not a TetSkin binding: field data '") + name + "' is missing");
  return a->GetValue(0);
}

vtkDataArray* pointArray(vtkPolyData* data, const char* name, int components,
                         const std::string& source) {
  vtkDataArray* a = data->GetPointData()->GetArray(name);
  if (!a || a->GetNumberOfTuples() != data->GetNumberOfPoints() ||
      (components > 0 && a->GetNumberOfComponents() != components))
    throw Error(source, 0,
                std::string("is not a TetSkin binding: point array '") + name +
                    "' is missing or has the wrong size");
  return a;
}

// `points`, the points of `data` (marked deformed), less its Displacement array.
Points3 lessDisplacement(vtkPolyData* data, Points3 points, const std::string& source) {
  const std::optional<Points3> displacement =
      fromVtkVectors(data->GetPointData()->GetArray(arrays::kDisplacement));
  if (!displacement || displacement->rows() != points.rows())
    throw Error(source, 0,
                "is a deformed surface (field data Pose 'deformed') without its rest shape: "
                "point array 'Displacement' is missing or has the wrong size");
  points -= *displacement;
  return points;
}

}  // namespace

void addBindingArrays(vtkPolyData* data, const SurfaceBinding& b) {
  const int k = b.controlsPerVertex();
  vtkPointData* pd = data->GetPointData();
  pd->AddArray(columns<vtkIntArray>(arrays::kControlIds, b.controlIds, k));
  pd->AddArray(columns<vtkDoubleArray>(arrays::kWeights, b.weights, k));
  pd->AddArray(columns<vtkDoubleArray>(arrays::kDistance, b.distance, 1));
  pd->AddArray(columns<vtkDoubleArray>(arrays::kMinBarycentric, b.minBarycentric, 1));
  pd->AddArray(columns<vtkIntArray>(arrays::kFaceId, b.faceId, 1));
  vtkFieldData* fd = data->GetFieldData();
  addString(fd, "Method", toString(b.method));
  addString(fd, "Offset", toString(b.offset));
  auto level = vtkSmartPointer<vtkIntArray>::New();
  level->SetName(arrays::kLevel);
  level->InsertNextValue(b.level);
  fd->AddArray(level);
  addString(fd, "Pose", "rest");
}

void markDeformed(vtkPolyData* data, vtkDoubleArray* displacement) {
  displacement->SetName(arrays::kDisplacement);
  data->GetPointData()->AddArray(displacement);
  addString(data->GetFieldData(), "Pose", "deformed");
}

bool isDeformed(vtkPolyData* data, const std::string& source) {
  auto* pose = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("Pose"));
  if (!pose || pose->GetNumberOfValues() < 1) return false;  // written before the pose was
  const std::string value = pose->GetValue(0);
  if (value != "rest" && value != "deformed")
    throw Error(source, 0, "field data 'Pose' is '" + value + "', not rest or deformed");
  return value == "deformed";
}

Points3 restPoints(vtkPolyData* data, const std::string& source) {
  Points3 points = fromVtkPoints(data->GetPoints(), source);
  if (!isDeformed(data, source)) return points;
  return lessDisplacement(data, std::move(points), source);
}

SurfaceMesh shownSurface(const BoundSurface& bound) {
  if (!bound.deformed) return bound.surface;
  if (bound.deformed->positions.rows() != bound.surface.vertexCount())
    throw Error("the deformed surface has " + std::to_string(bound.deformed->positions.rows()) +
                " vertices, its binding " + std::to_string(bound.surface.vertexCount()));
  SurfaceMesh moved = bound.surface;
  moved.positions = bound.deformed->positions;
  moved.normals = bound.deformed->normals;
  return moved;
}

vtkSmartPointer<vtkPolyData> bindingToPolyData(const BoundSurface& bound) {
  vtkSmartPointer<vtkPolyData> data = toVtkPolyData(shownSurface(bound));
  addBindingArrays(data, bound.binding);
  if (bound.deformed) {
    markDeformed(data, toVtkVectors(arrays::kDisplacement,
                                    bound.deformed->positions - bound.surface.positions));
    for (const PointScalars& scalars : bound.deformed->scalars) {
      if (scalars.values.size() != bound.surface.vertexCount())
        throw Error("the deformed surface's " + scalars.name + ": " +
                    std::to_string(scalars.values.size()) + " values for " +
                    std::to_string(bound.surface.vertexCount()) + " vertices");
      data->GetPointData()->AddArray(toVtkScalars(scalars.name.c_str(), scalars.values));
    }
    for (const PointVectors& vectors : bound.deformed->vectors) {
      if (vectors.values.rows() != bound.surface.vertexCount())
        throw Error("the deformed surface's " + vectors.name + ": " +
                    std::to_string(vectors.values.rows()) + " vectors for " +
                    std::to_string(bound.surface.vertexCount()) + " vertices");
      data->GetPointData()->AddArray(toVtkVectors(vectors.name.c_str(), vectors.values));
    }
  }
  addString(data->GetFieldData(), "Dataset", bound.dataset);
  return data;
}

bool isBinding(vtkPolyData* data) {
  vtkFieldData* fd = data ? data->GetFieldData() : nullptr;
  return fd && fd->GetAbstractArray("Dataset") && fd->GetAbstractArray("Method") &&
         fd->GetAbstractArray(arrays::kLevel);
}

SurfaceBinding bindingArraysFromPolyData(vtkPolyData* data, const std::string& source) {
  if (!data) throw Error(source, 0, "no surface");
  vtkFieldData* fd = data->GetFieldData();
  SurfaceBinding b;
  const auto method = parseName<BindingMethod>(getString(fd, "Method", source));
  const auto offset = parseName<OffsetMode>(getString(fd, "Offset", source));
  if (!method || !offset) throw Error(source, 0, "unknown binding method or offset mode");
  b.method = *method;
  b.offset = *offset;
  auto* level = vtkIntArray::SafeDownCast(fd->GetArray(arrays::kLevel));
  if (!level || level->GetNumberOfValues() < 1)
    throw Error(source, 0, "field data 'Level' is missing");
  b.level = level->GetValue(0);
  const Index n = data->GetNumberOfPoints();
  b.resize(n);
  const int k = b.controlsPerVertex();
  vtkDataArray* ids = pointArray(data, arrays::kControlIds, k, source);
  vtkDataArray* weights = pointArray(data, arrays::kWeights, k, source);
  vtkDataArray* distance = pointArray(data, arrays::kDistance, 1, source);
  vtkDataArray* minBary = pointArray(data, arrays::kMinBarycentric, 1, source);
  vtkDataArray* face = pointArray(data, arrays::kFaceId, 1, source);
  for (Index v = 0; v < n; ++v) {
    for (int c = 0; c < k; ++c) {
      b.controlIds(v, c) = static_cast<int>(ids->GetComponent(v, c));
      b.weights(v, c) = weights->GetComponent(v, c);
    }
    b.distance[v] = distance->GetComponent(v, 0);
    b.minBarycentric[v] = minBary->GetComponent(v, 0);
    b.faceId[v] = static_cast<int>(face->GetComponent(v, 0));
  }
  return b;
}

BoundSurface bindingFromPolyData(vtkPolyData* data, const std::string& source) {
  BoundSurface bound;
  bound.surface = fromVtkPolyData(data, source);
  bound.dataset = getString(data->GetFieldData(), "Dataset", source);
  if (data->GetNumberOfPoints() != bound.surface.vertexCount())
    throw Error(source, 0, "the binding's points were merged or dropped on reading");
  bound.binding = bindingArraysFromPolyData(data, source);
  if (isDeformed(data, source)) {
    bound.deformed = DeformedState{bound.surface.positions, bound.surface.normals};
    bound.surface.positions = lessDisplacement(data, bound.surface.positions, source);
    bound.surface.normals.resize(0, 3);  // (the rest normals were not written)
  }
  return bound;
}

std::string datasetField(const std::filesystem::path& dataset, const std::filesystem::path& file) {
  if (dataset.empty()) return {};
  const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
  return std::filesystem::relative(std::filesystem::absolute(dataset), folder).generic_string();
}

std::string datasetOfField(const std::string& field, const std::filesystem::path& file) {
  if (field.empty()) return {};
  return (file.parent_path() / field).lexically_normal().generic_string();
}

namespace {

// What a binding file at `path` holds: its Dataset named from the file's folder.
vtkSmartPointer<vtkPolyData> bindingFileData(const std::filesystem::path& path,
                                             const BoundSurface& bound) {
  const vtkSmartPointer<vtkPolyData> data = bindingToPolyData(bound);
  addString(data->GetFieldData(), "Dataset", datasetField(bound.dataset, path));  // (replaces)
  return data;
}

}  // namespace

void writeBinding(const std::filesystem::path& path, const BoundSurface& bound) {
  if (lowerExtension(path) == ".pvtp") return writeBinding(path, bound, restPieces(bound, 1));
  writeVtp(path, bindingFileData(path, bound));
}

void writeBinding(const std::filesystem::path& path, const BoundSurface& bound,
                  const std::vector<SurfacePiece>& pieces) {
  if (lowerExtension(path) != ".pvtp")
    throw Error(path.string(), 0, "a surface in pieces is written as a .pvtp");
  writePvtp(path, bindingFileData(path, bound), pieces);
}

std::vector<SurfacePiece> restPieces(const BoundSurface& bound, int count) {
  const SurfaceMesh& rest = bound.surface;
  return splitSurface(rest.vertexCount(), rest.triangles,
                      surfacePieces(rest.positions, rest.triangles, count));
}

BoundSurface bindingFromFile(vtkPolyData* data, const std::filesystem::path& path) {
  BoundSurface bound = bindingFromPolyData(data, path.string());
  bound.dataset = datasetOfField(bound.dataset, path);
  return bound;
}

BoundSurface readBinding(const std::filesystem::path& path) {
  return bindingFromFile(readVtp(path), path);
}

BoundSurface readBinding(const std::filesystem::path& path, const MultiLevelTetMesh& dataset) {
  BoundSurface bound = readBinding(path);
  checkBindingFits(bound, dataset, path.string());
  return bound;
}

SurfaceOrBinding readSurfaceOrBinding(const std::filesystem::path& path) {
  if (lowerExtension(path) != ".vtp") return {readSurface(path), std::nullopt, {}};
  const vtkSmartPointer<vtkPolyData> data = readVtp(path);
  if (!isBinding(data)) return {fromVtkPolyData(data, path.string()), std::nullopt, {}};
  BoundSurface bound = bindingFromFile(data, path);
  return {std::move(bound.surface), std::move(bound.binding), std::move(bound.dataset)};
}

SurfaceOrBinding readSurfaceOrBinding(const std::filesystem::path& path,
                                      const MultiLevelTetMesh& dataset) {
  SurfaceOrBinding read = readSurfaceOrBinding(path);
  if (read.binding)
    checkBindingFits(*read.binding, read.surface.vertexCount(), dataset, path.string());
  return read;
}

void checkBindingFits(const SurfaceBinding& b, Index surfaceVertices,
                      const MultiLevelTetMesh& dataset, const std::string& name) {
  validateBinding(b, surfaceVertices, dataset.nodes.rows(), name);
  if (b.level < 0 || b.level >= dataset.levelCount())
    throw Error(name, 0,
                "is bound to level " + std::to_string(b.level) +
                    ", but the dataset has levels 0.." + std::to_string(dataset.levelCount() - 1));
  const LevelRange& range = dataset.levels[static_cast<std::size_t>(b.level)];
  for (Index v = 0; v < b.vertexCount(); ++v)
    for (int c = 0; c < b.controlsPerVertex(); ++c) {
      const int id = b.controlIds(v, c);
      if (id < range.firstNode || id >= range.firstNode + range.nodeCount)
        throw Error(name, 0,
                    "vertex " + std::to_string(v) + " is bound to node " + std::to_string(id) +
                        ", outside level " + std::to_string(b.level) + "'s nodes [" +
                        std::to_string(range.firstNode) + ", " +
                        std::to_string(range.firstNode + range.nodeCount) +
                        ") (a binding made for another dataset?)");
    }
}

}  // namespace tetskin
