// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/vtkio/VtkConversion.h"

namespace tetskin {
namespace {

SurfaceMesh triangle() {
  SurfaceMesh m;
  m.positions.resize(3, 3);
  m.positions << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  m.normals = Points3::Zero(3, 3);
  m.normals.col(2).setOnes();
  m.texcoords.resize(3, 2);
  m.texcoords << 0, 0, 1, 0, 0, 1;
  return m;
}

// VTK orders bounds by axis, each min before max.
TEST(VtkConversion, BoxAsVtkBounds) {
  BoundingBox box;
  box.extend(Eigen::Vector3d(1, -2, 3));
  box.extend(Eigen::Vector3d(4, 5, -6));
  EXPECT_EQ(toVtkBounds(box), (std::array<double, 6>{1, 4, -2, 5, -6, 3}));
}

TEST(VtkConversion, SurfaceRoundTripKeepsAttributes) {
  const SurfaceMesh m = triangle();
  vtkSmartPointer<vtkPolyData> pd = toVtkPolyData(m);
  EXPECT_EQ(pd->GetNumberOfPoints(), 3);
  EXPECT_EQ(pd->GetNumberOfPolys(), 1);
  ASSERT_NE(pd->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(pd->GetPointData()->GetTCoords(), nullptr);
  const SurfaceMesh back = fromVtkPolyData(pd, "t");
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.normals, m.normals);
  EXPECT_EQ(back.texcoords, m.texcoords);
}

TEST(VtkConversion, VectorRowsAreTheArraysOwnBuffer) {
  const Points3 values = (Points3(2, 3) << 1, 2, 3, 4, 5, 6).finished();
  const vtkSmartPointer<vtkDoubleArray> array = toVtkVectors("Normals", values);
  Eigen::Map<Points3> rows = vectorRows(array);
  EXPECT_EQ(rows, values);
  rows(1, 2) = 7;  // written through, not into a copy
  EXPECT_EQ(array->GetComponent(1, 2), 7.0);
  vtkNew<vtkDoubleArray> pairs;
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(3);
  EXPECT_THROW(vectorRows(pairs), Error);
  EXPECT_THROW(vectorRows(nullptr), Error);
}

// Arrays read from files come in any value type (ParaView writes float).
TEST(VtkConversion, VectorsOfAnyValueTypeCopyToRows) {
  vtkNew<vtkFloatArray> floats;
  floats->SetNumberOfComponents(3);
  floats->SetNumberOfTuples(2);
  for (int i = 0; i < 6; ++i) floats->SetValue(i, 0.5f * static_cast<float>(i));
  const std::optional<Points3> rows = fromVtkVectors(floats);
  ASSERT_TRUE(rows.has_value());
  EXPECT_EQ(*rows, (Points3(2, 3) << 0, 0.5, 1, 1.5, 2, 2.5).finished());
  floats->SetValue(0, 9.0f);
  EXPECT_EQ((*rows)(0, 0), 0.0);  // a copy
  vtkNew<vtkFloatArray> pairs;
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(3);
  EXPECT_FALSE(fromVtkVectors(pairs).has_value());
  EXPECT_FALSE(fromVtkVectors(nullptr).has_value());
}

TEST(VtkConversion, QuadsAreTriangulated) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (double p : {0.0, 1.0})
    for (double q : {0.0, 1.0}) pts->InsertNextPoint(p, q, 0);
  pd->SetPoints(pts);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[] = {0, 2, 3, 1};
  polys->InsertNextCell(4, quad);
  pd->SetPolys(polys);
  const SurfaceMesh m = fromVtkPolyData(pd, "quad");
  EXPECT_EQ(m.triangleCount(), 2);
  EXPECT_NEAR(surfaceArea(m), 1.0, 1e-12);
}

TEST(VtkConversion, EmptyPolyDataIsAnError) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  EXPECT_THROW(fromVtkPolyData(pd, "empty"), Error);
  EXPECT_THROW(fromVtkPolyData(nullptr, "null"), Error);
}

TEST(VtkConversion, TetMeshRoundTrip) {
  const TetMesh m = test::unitTetrahedron();
  vtkSmartPointer<vtkUnstructuredGrid> grid = toVtkUnstructuredGrid(m);
  EXPECT_EQ(grid->GetNumberOfCells(), 1);
  EXPECT_EQ(grid->GetCellType(0), VTK_TETRA);
  const TetMesh back = fromVtkUnstructuredGrid(grid, "g");
  EXPECT_EQ(back.nodes, m.nodes);
  EXPECT_EQ(back.elements, m.elements);
}

TEST(VtkConversion, NonTetraCellIsNamed) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (int i = 0; i < 4; ++i) pts->InsertNextPoint(i, i * i, 0);
  grid->SetPoints(pts);
  const vtkIdType tri[] = {0, 1, 2};
  grid->InsertNextCell(VTK_TRIANGLE, 3, tri);
  try {
    fromVtkUnstructuredGrid(grid, "g.vtu");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0 is a vtkTriangle"), std::string::npos) << e.what();
  }
}

// A mesh made elsewhere (Gmsh through meshio writes boundary triangles,
// edges and vertices beside the tetrahedra): the lower cells are left out
// and counted; another 3D cell is named; a mesh of no tetrahedra is refused.
TEST(VtkConversion, ImportedTetrahedraLeaveOutLowerCells) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                        Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)})
    pts->InsertNextPoint(p.data());
  grid->SetPoints(pts);
  const vtkIdType vertex[] = {0}, line[] = {0, 1}, tri[] = {0, 1, 2}, tet[] = {0, 1, 2, 3};
  grid->InsertNextCell(VTK_VERTEX, 1, vertex);
  grid->InsertNextCell(VTK_LINE, 2, line);
  grid->InsertNextCell(VTK_TRIANGLE, 3, tri);
  EXPECT_NE(test::errorText([&] {
              tetrahedraOf(grid, "flat.vtu");
            }).find("flat.vtu: has no tetrahedra (3 cells of lower dimension)"),
            std::string::npos);
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  const ImportedTetrahedra imported = tetrahedraOf(grid, "mixed.vtu");
  EXPECT_EQ(imported.skippedCells, 3);
  ASSERT_EQ(imported.mesh.elementCount(), 1);
  EXPECT_EQ(imported.mesh.elements.row(0), Eigen::RowVector4i(0, 1, 2, 3));
  const vtkIdType wedge[] = {0, 1, 2, 3, 1, 2};
  grid->InsertNextCell(VTK_WEDGE, 6, wedge);
  EXPECT_NE(test::errorText([&] {
              tetrahedraOf(grid, "mixed.vtu");
            }).find("mixed.vtu: cell 4 is a vtkWedge, not a linear tetrahedron"),
            std::string::npos);
}

}  // namespace
}  // namespace tetskin
