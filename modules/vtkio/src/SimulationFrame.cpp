// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/SimulationFrame.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

// Point array `name` of `grid` as rows, each checked to be finite.
Points3 pointVectors(vtkUnstructuredGrid* grid, const char* name, const std::string& source) {
  std::optional<Points3> out = fromVtkVectors(grid->GetPointData()->GetArray(name));
  if (!out || out->rows() != grid->GetNumberOfPoints())
    throw Error(source, 0,
                std::string("is not a simulation frame: point array '") + name +
                    "' is missing or not one 3-vector per point");
  for (Index i = 0; i < out->rows(); ++i)
    if (const std::string problem = coordinateProblem(out->row(i)); !problem.empty())
      throw Error(source, 0, std::string(name) + " of point " + std::to_string(i) + " " + problem);
  return std::move(*out);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> simulationFrame(const TetMesh& rest, const FrameFields& fields,
                                                     int level, const RunConditions& conditions) {
  const Index nodes = rest.nodeCount();
  requireRows("the frame's positions", fields.positions.rows(), nodes, "nodes");
  requireRows("the frame's velocities", fields.velocities.rows(), nodes, "nodes");
  requireRows("the frame's external forces", fields.externalForces.rows(), nodes, "nodes");
  requireRows("the frame's reaction forces", fields.reactionForces.rows(), nodes, "nodes");
  requireRows("the frame's stresses", fields.vonMisesStress.size(), rest.elementCount(),
              "elements");
  requireRows("the frame's strains", fields.equivalentStrain.size(), rest.elementCount(),
              "elements");
  TetMesh deformed{fields.positions, rest.elements};
  vtkSmartPointer<vtkUnstructuredGrid> grid = toVtkUnstructuredGrid(deformed);
  grid->GetPointData()->AddArray(
      toVtkVectors(arrays::kDisplacement, fields.positions - rest.nodes));
  grid->GetPointData()->AddArray(toVtkVectors(arrays::kVelocity, fields.velocities));
  grid->GetPointData()->AddArray(toVtkVectors(arrays::kExternalForce, fields.externalForces));
  grid->GetPointData()->AddArray(toVtkVectors(arrays::kReactionForce, fields.reactionForces));
  if (fields.contactForces.rows() > 0) {
    requireRows("the frame's contact forces", fields.contactForces.rows(), nodes, "nodes");
    grid->GetPointData()->AddArray(toVtkVectors(arrays::kContactForce, fields.contactForces));
  }
  // 0/1 per node rather than a list: ParaView thresholds or colours by it.
  auto prescribed = vtkSmartPointer<vtkUnsignedCharArray>::New();
  prescribed->SetName(arrays::kPrescribed);
  prescribed->SetNumberOfValues(rest.nodeCount());
  prescribed->FillValue(0);
  for (int node : conditions.prescribedNodes) {
    if (node < 0 || node >= rest.nodeCount())
      throw Error("prescribed node " + std::to_string(node) + " does not exist (the mesh has " +
                  std::to_string(rest.nodeCount()) + " nodes)");
    prescribed->SetValue(node, 1);
  }
  grid->GetPointData()->AddArray(prescribed);
  auto stress = vtkSmartPointer<vtkDoubleArray>::New();
  stress->SetName(arrays::kVonMisesStress);
  auto strain = vtkSmartPointer<vtkDoubleArray>::New();
  strain->SetName(arrays::kEquivalentStrain);
  auto ratio = vtkSmartPointer<vtkDoubleArray>::New();
  ratio->SetName("VolumeRatio");
  auto levels = vtkSmartPointer<vtkIntArray>::New();
  levels->SetName(arrays::kLevel);
  stress->SetNumberOfValues(rest.elementCount());
  strain->SetNumberOfValues(rest.elementCount());
  ratio->SetNumberOfValues(rest.elementCount());
  levels->SetNumberOfValues(rest.elementCount());
  for (Index e = 0; e < rest.elementCount(); ++e) {
    stress->SetValue(e, fields.vonMisesStress[e]);
    strain->SetValue(e, fields.equivalentStrain[e]);
    ratio->SetValue(e, elementVolume(deformed, e) / elementVolume(rest, e));
    levels->SetValue(e, level);
  }
  grid->GetCellData()->AddArray(stress);
  grid->GetCellData()->AddArray(strain);
  grid->GetCellData()->AddArray(ratio);
  grid->GetCellData()->AddArray(levels);
  if (fields.stress.rows() > 0) {
    requireRows("the frame's stress tensors", fields.stress.rows(), rest.elementCount(),
                "elements");
    auto tensors = vtkSmartPointer<vtkDoubleArray>::New();
    tensors->SetName(arrays::kStress);
    tensors->SetNumberOfComponents(6);
    tensors->SetNumberOfTuples(rest.elementCount());
    for (Index e = 0; e < rest.elementCount(); ++e)
      tensors->SetTypedTuple(e, fields.stress.row(e).data());
    grid->GetCellData()->AddArray(tensors);
  }
  if (const std::optional<FloorPlane>& floor = conditions.floor) {
    // As a plane ParaView's users can read: its normal and its height
    // along it.
    grid->GetFieldData()->AddArray(toVtkVectors("FloorNormal", upVector(floor->up).transpose()));
    auto height = vtkSmartPointer<vtkDoubleArray>::New();
    height->SetName("FloorHeight");
    height->InsertNextValue(floor->height);
    grid->GetFieldData()->AddArray(height);
  }
  return grid;
}

FrameState readSimulationFrame(const std::filesystem::path& path, const TetMesh& rest,
                               const std::string& restName) {
  const std::string source = path.string();
  vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(path);
  const TetMesh frame = fromVtkUnstructuredGrid(grid, source);
  if (frame.nodeCount() != rest.nodeCount() || frame.elementCount() != rest.elementCount())
    throw Error(source, 0,
                "has " + std::to_string(frame.nodeCount()) + " points and " +
                    std::to_string(frame.elementCount()) + " tetrahedra; " + restName + " has " +
                    std::to_string(rest.nodeCount()) + " and " +
                    std::to_string(rest.elementCount()));
  for (Index e = 0; e < rest.elementCount(); ++e)
    if (frame.elements.row(e) != rest.elements.row(e))
      throw Error(source, 0,
                  "tetrahedron " + std::to_string(e) + " has other nodes than in " + restName);
  const Points3 displacement = pointVectors(grid, arrays::kDisplacement, source);
  FrameState state{frame.nodes, pointVectors(grid, arrays::kVelocity, source)};
  // The frame's rest shape must be this one: the displacement was taken
  // from it, so within rounding of the largest coordinate.
  const Points3 frameRest = frame.nodes - displacement;
  const double scale =
      std::max({rest.nodes.cwiseAbs().maxCoeff(), frame.nodes.cwiseAbs().maxCoeff(), 1e-300});
  for (Index v = 0; v < rest.nodeCount(); ++v)
    if ((frameRest.row(v) - rest.nodes.row(v)).cwiseAbs().maxCoeff() > 1e-9 * scale)
      throw Error(source, 0,
                  "point " + std::to_string(v) +
                      ": its position less its Displacement is not its rest position in " +
                      restName + " (a frame of another body)");
  const auto elementValues = [&](const char* name) {
    vtkDataArray* array = grid->GetCellData()->GetArray(name);
    Eigen::VectorXd values;
    if (!array || array->GetNumberOfComponents() != 1 ||
        array->GetNumberOfTuples() != rest.elementCount())
      return values;
    values.resize(rest.elementCount());
    for (Index e = 0; e < rest.elementCount(); ++e) values[e] = array->GetTuple1(e);
    if (!values.allFinite()) values.resize(0);
    return values;
  };
  state.vonMisesStress = elementValues(arrays::kVonMisesStress);
  state.equivalentStrain = elementValues(arrays::kEquivalentStrain);
  if (vtkDataArray* tensors = grid->GetCellData()->GetArray(arrays::kStress);
      tensors && tensors->GetNumberOfComponents() == 6 &&
      tensors->GetNumberOfTuples() == rest.elementCount()) {
    state.stress.resize(rest.elementCount(), 6);
    for (Index e = 0; e < rest.elementCount(); ++e)
      for (int c = 0; c < 6; ++c) state.stress(e, c) = tensors->GetComponent(e, c);
    if (!state.stress.allFinite()) state.stress.resize(0, 6);
  }
  return state;
}

TetMesh readFrameRest(const std::filesystem::path& path) {
  const std::string source = path.string();
  vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(path);
  TetMesh frame = fromVtkUnstructuredGrid(grid, source);
  frame.nodes -= pointVectors(grid, arrays::kDisplacement, source);
  return frame;
}

SimulationFrameFacts simulationFrameFacts(const std::filesystem::path& path) {
  vtkSmartPointer<vtkUnstructuredGrid> grid = readVtu(path);
  SimulationFrameFacts facts;
  facts.nodeCount = grid->GetNumberOfPoints();
  facts.elementCount = grid->GetNumberOfCells();
  vtkDataArray* levels = grid->GetCellData()->GetArray(arrays::kLevel);
  if (levels && levels->GetNumberOfTuples() > 0 && levels->GetNumberOfComponents() == 1)
    facts.level = static_cast<int>(levels->GetTuple1(0));
  vtkDataArray* normal = grid->GetFieldData()->GetArray("FloorNormal");
  vtkDataArray* height = grid->GetFieldData()->GetArray("FloorHeight");
  if (normal && height && normal->GetNumberOfTuples() == 1 &&
      normal->GetNumberOfComponents() == 3 && height->GetNumberOfTuples() == 1 &&
      height->GetNumberOfComponents() == 1 && std::isfinite(height->GetTuple1(0))) {
    // (Only an axis is a floor this program simulates.)
    const double* n = normal->GetTuple3(0);
    for (UpAxis up : {UpAxis::X, UpAxis::Y, UpAxis::Z})
      if (Eigen::Vector3d(n[0], n[1], n[2]) == upVector(up))
        facts.conditions.floor = FloorPlane{up, height->GetTuple1(0)};
  }
  vtkDataArray* prescribed = grid->GetPointData()->GetArray(arrays::kPrescribed);
  if (prescribed && prescribed->GetNumberOfComponents() == 1 &&
      prescribed->GetNumberOfTuples() == grid->GetNumberOfPoints())
    for (vtkIdType v = 0; v < prescribed->GetNumberOfTuples(); ++v)
      if (prescribed->GetTuple1(v) != 0)
        facts.conditions.prescribedNodes.push_back(static_cast<int>(v));
  return facts;
}

}  // namespace tetskin
