// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/VtkConversion.h"

#include <vtkCellArray.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

namespace tetskin {
namespace {

// Fixed-size connectivity: offsets 0, k, 2k, ... and the flattened ids.
template <int K, typename Matrix>
vtkSmartPointer<vtkCellArray> toCells(const Matrix& cells) {
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(cells.rows() + 1);
  connectivity->SetNumberOfValues(cells.rows() * K);
  for (Index c = 0; c <= cells.rows(); ++c) offsets->SetValue(c, c * K);
  for (Index c = 0; c < cells.rows(); ++c)
    for (int k = 0; k < K; ++k) connectivity->SetValue(c * K + k, cells(c, k));
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->SetData(offsets, connectivity);
  return out;
}

}  // namespace

vtkSmartPointer<vtkPoints> toVtkPoints(const Points3& points) {
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(points.rows());
  for (Index i = 0; i < points.rows(); ++i)
    out->SetPoint(i, points(i, 0), points(i, 1), points(i, 2));
  return out;
}

vtkSmartPointer<vtkDoubleArray> toVtkVectors(const char* name, const Points3& values) {
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(name);
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(values.rows());
  for (Index i = 0; i < values.rows(); ++i) out->SetTuple(i, values.row(i).data());
  return out;
}

vtkSmartPointer<vtkDoubleArray> toVtkScalars(const char* name, const Eigen::VectorXd& values) {
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(name);
  out->SetNumberOfValues(values.size());
  for (Index i = 0; i < values.size(); ++i) out->SetValue(i, values[i]);
  return out;
}

vtkSmartPointer<vtkMatrix4x4> toVtkMatrix(const Eigen::Affine3d& map) {
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix->SetElement(r, c, map.matrix()(r, c));
  return matrix;
}

Eigen::Map<Points3> vectorRows(vtkDoubleArray* array) {
  if (!array || array->GetNumberOfComponents() != 3)
    throw Error("vector rows: " +
                (array ? std::to_string(array->GetNumberOfComponents()) + " components instead of 3"
                       : std::string("no double array")));
  return Eigen::Map<Points3>(array->GetPointer(0), array->GetNumberOfTuples(), 3);
}

std::optional<Points3> fromVtkVectors(vtkDataArray* array) {
  if (!array || array->GetNumberOfComponents() != 3) return std::nullopt;
  Points3 out(array->GetNumberOfTuples(), 3);
  for (Index i = 0; i < out.rows(); ++i)
    for (int k = 0; k < 3; ++k) out(i, k) = array->GetComponent(i, k);
  return out;
}

Points3 fromVtkPoints(vtkPoints* points, const std::string& sourceName) {
  const Index n = points ? points->GetNumberOfPoints() : 0;
  Points3 out(n, 3);
  for (Index i = 0; i < n; ++i) {
    double p[3];
    points->GetPoint(i, p);
    out.row(i) << p[0], p[1], p[2];
    const std::string problem = coordinateProblem(out.row(i));
    if (!problem.empty()) throw Error(sourceName, 0, "point " + std::to_string(i) + " " + problem);
  }
  return out;
}

vtkSmartPointer<vtkPolyData> toVtkPolyData(const SurfaceMesh& mesh) {
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(toVtkPoints(mesh.positions));
  out->SetPolys(toCells<3>(mesh.triangles));
  if (mesh.hasNormals())
    out->GetPointData()->SetNormals(toVtkVectors(arrays::kNormals, mesh.normals));
  if (mesh.hasTexcoords()) {
    auto tcoords = vtkSmartPointer<vtkDoubleArray>::New();
    tcoords->SetName("TCoords");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(mesh.texcoords.rows());
    for (Index i = 0; i < mesh.texcoords.rows(); ++i)
      tcoords->SetTuple(i, mesh.texcoords.row(i).data());
    out->GetPointData()->SetTCoords(tcoords);
  }
  return out;
}

SurfaceMesh fromVtkPolyData(vtkPolyData* polyData, const std::string& sourceName) {
  if (!polyData || polyData->GetNumberOfPolys() == 0)
    throw Error(sourceName, 0, "contains no triangles");
  vtkSmartPointer<vtkPolyData> triangulated = polyData;
  if (polyData->GetPolys()->IsHomogeneous() != 3) {
    auto filter = vtkSmartPointer<vtkTriangleFilter>::New();
    filter->SetInputData(polyData);
    filter->PassVertsOff();
    filter->PassLinesOff();
    filter->Update();
    triangulated = filter->GetOutput();
  }
  SurfaceMesh mesh;
  mesh.positions = fromVtkPoints(triangulated->GetPoints(), sourceName);
  vtkCellArray* polys = triangulated->GetPolys();
  mesh.triangles.resize(polys->GetNumberOfCells(), 3);
  Index t = 0;
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids); ++t) {
    if (size != 3)
      throw Error(sourceName, 0, "polygon " + std::to_string(t) + " could not be triangulated");
    for (int k = 0; k < 3; ++k) mesh.triangles(t, k) = static_cast<int>(ids[k]);
  }
  vtkPointData* pd = triangulated->GetPointData();
  if (std::optional<Points3> normals = fromVtkVectors(pd->GetNormals()))
    mesh.normals = std::move(*normals);
  if (vtkDataArray* tc = pd->GetTCoords(); tc && tc->GetNumberOfComponents() >= 2) {
    mesh.texcoords.resize(tc->GetNumberOfTuples(), 2);
    for (Index i = 0; i < mesh.texcoords.rows(); ++i)
      for (int k = 0; k < 2; ++k) mesh.texcoords(i, k) = tc->GetComponent(i, k);
  }
  validateSurface(mesh, sourceName);
  return mesh;
}

vtkSmartPointer<vtkUnstructuredGrid> toVtkUnstructuredGrid(const TetMesh& mesh) {
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(toVtkPoints(mesh.nodes));
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  types->SetNumberOfValues(mesh.elementCount());
  types->FillValue(VTK_TETRA);
  out->SetCells(types, toCells<4>(mesh.elements));
  return out;
}

ImportedTetrahedra tetrahedraOf(vtkUnstructuredGrid* grid, const std::string& sourceName) {
  if (!grid || grid->GetNumberOfCells() == 0) throw Error(sourceName, 0, "contains no cells");
  ImportedTetrahedra out;
  auto cell = vtkSmartPointer<vtkGenericCell>::New();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const int type = grid->GetCellType(c);
    if (type == VTK_TETRA) {
      out.cells.push_back(c);
      continue;
    }
    grid->GetCell(c, cell);
    if (cell->GetCellDimension() < 3) {
      ++out.skippedCells;
    } else {
      throw Error(sourceName, 0,
                  "cell " + std::to_string(c) + " is a " +
                      vtkCellTypes::GetClassNameFromTypeId(type) +
                      ", not a linear tetrahedron (split the mesh into linear tetrahedra first)");
    }
  }
  if (out.cells.empty())
    throw Error(sourceName, 0,
                "has no tetrahedra (" + std::to_string(out.skippedCells) +
                    " cells of lower dimension): a volume mesh is needed");
  out.mesh.nodes = fromVtkPoints(grid->GetPoints(), sourceName);
  out.mesh.elements.resize(static_cast<Index>(out.cells.size()), 4);
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (std::size_t e = 0; e < out.cells.size(); ++e) {
    grid->GetCellPoints(out.cells[e], size, ids);
    for (int k = 0; k < 4; ++k)
      out.mesh.elements(static_cast<Index>(e), k) = static_cast<int>(ids[k]);
  }
  validateTetMesh(out.mesh, sourceName, /*requirePositiveVolume=*/false);
  return out;
}

TetMesh fromVtkUnstructuredGrid(vtkUnstructuredGrid* grid, const std::string& sourceName) {
  // (Strict: where tetrahedraOf leaves a lower cell out, this names it.)
  if (grid)
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
      if (grid->GetCellType(c) != VTK_TETRA)
        throw Error(sourceName, 0,
                    "cell " + std::to_string(c) + " is a " +
                        vtkCellTypes::GetClassNameFromTypeId(grid->GetCellType(c)) +
                        ", not a linear tetrahedron");
  return tetrahedraOf(grid, sourceName).mesh;
}

}  // namespace tetskin
