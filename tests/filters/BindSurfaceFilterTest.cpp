// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkHexahedron.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "FilterTestData.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/filters/vtkTetSkinBindSurface.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin::test {
namespace {

TEST(BindSurfaceFilter, EqualsTheBindingOfTheCommandLineInTheGridsNumbering) {
  const vtkSmartPointer<vtkPolyData> surface = toVtkPolyData(bunnySurface());
  vtkNew<vtkIntArray> custom;  // an array of the user's, to be passed on
  custom->SetName("Custom");
  custom->SetNumberOfTuples(surface->GetNumberOfPoints());
  custom->FillValue(7);
  surface->GetPointData()->AddArray(custom);

  for (int method : {vtkTetSkinBindSurface::CLOSEST, vtkTetSkinBindSurface::SEED,
                     vtkTetSkinBindSurface::EMBED}) {
    SCOPED_TRACE("method " + std::to_string(method));
    vtkNew<vtkTetSkinBindSurface> bind;
    bind->SetInputData(surface);
    bind->SetControlMeshData(controlLevelGrid());
    bind->SetMethod(method);
    bind->Update();
    vtkPolyData* out = bind->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), surface->GetNumberOfPoints());
    EXPECT_EQ(out->GetNumberOfPolys(), surface->GetNumberOfPolys());
    ASSERT_NE(out->GetPointData()->GetArray("Custom"), nullptr);
    const SurfaceBinding fromFilter = bindingArraysFromPolyData(out, "filter output");

    // `tetskin bind` on the whole dataset: the same choices, its ids shifted
    // by the level's first node.
    BindingOptions options;
    options.method = method == vtkTetSkinBindSurface::SEED    ? BindingMethod::Seed
                     : method == vtkTetSkinBindSurface::EMBED ? BindingMethod::Embed
                                                              : BindingMethod::Closest;
    const SurfaceBinding reference =
        bindSurface(bunnySurface(), sampleDataset().mesh, kBoundLevel, options);
    const int k = reference.controlsPerVertex();
    ASSERT_EQ(fromFilter.controlsPerVertex(), k);
    const int first = static_cast<int>(sampleDataset().mesh.levels[kBoundLevel].firstNode);
    ASSERT_GT(first, 0);
    EXPECT_EQ(fromFilter.controlIds.leftCols(k),
              (reference.controlIds.leftCols(k).array() - first).matrix());
    EXPECT_EQ(fromFilter.weights, reference.weights);
    EXPECT_EQ(fromFilter.distance, reference.distance);
    // FaceId is the element, for every method: a cell id of the grid.
    const int firstElement =
        static_cast<int>(sampleDataset().mesh.levels[kBoundLevel].firstElement);
    EXPECT_EQ(fromFilter.faceId, (reference.faceId.array() - firstElement).matrix());
    EXPECT_EQ(fromFilter.level, 0);
    EXPECT_EQ(fromFilter.method, reference.method);
  }
  // The input is left as it was.
  EXPECT_EQ(surface->GetPointData()->GetArray("ControlIds"), nullptr);
  EXPECT_EQ(surface->GetFieldData()->GetAbstractArray("Method"), nullptr);
}

TEST(BindSurfaceFilter, ParametersReachTheKernelAndRerunThePipeline) {
  vtkNew<vtkTetSkinBindSurface> bind;
  bind->SetInputData(toVtkPolyData(bunnySurface()));
  bind->SetControlMeshData(controlLevelGrid());
  bind->Update();
  EXPECT_EQ(bindingArraysFromPolyData(bind->GetOutput(), "out").offset, OffsetMode::Normal);
  bind->SetOffsetModeToDisplacement();
  bind->Update();  // a changed parameter runs the filter again
  EXPECT_EQ(bindingArraysFromPolyData(bind->GetOutput(), "out").offset, OffsetMode::Displacement);
  bind->SetMethod(99);  // clamped, as VTK's Set macros clamp
  EXPECT_EQ(bind->GetMethod(), vtkTetSkinBindSurface::EMBED);
}

// A surface far from the control mesh still binds, with a warning (as
// tetskin bind gives), not an error: ParaView shows it in its output window.
TEST(BindSurfaceFilter, ASurfaceFarFromTheControlMeshBindsWithAWarning) {
  SurfaceMesh moved = bunnySurface();
  moved.positions.col(1).array() += 20;
  for (const auto& [surface, far] : {std::pair{bunnySurface(), false}, std::pair{moved, true}}) {
    vtkNew<vtkTetSkinBindSurface> bind;
    const VtkErrorCapture messages(bind);
    bind->SetInputData(toVtkPolyData(surface));
    bind->SetControlMeshData(controlLevelGrid());
    bind->Update();
    EXPECT_FALSE(messages.failed());
    EXPECT_EQ(bind->GetOutput()->GetNumberOfPoints(), surface.vertexCount());
    const std::string message = messages.message("(nothing)");
    if (far) {
      EXPECT_NE(message.find("a tenth of the vertices lie more than "), std::string::npos)
          << message;
      EXPECT_NE(message.find("% of input 1 (control mesh)'s diagonal from its boundary"),
                std::string::npos)
          << message;
    } else {
      EXPECT_EQ(message, "(nothing)");
    }
  }
}

TEST(BindSurfaceFilter, BadInputIsAnErrorNamingTheInputAndElementAndAnEmptyOutput) {
  {  // a control mesh cell that is not a tetrahedron
    vtkSmartPointer<vtkUnstructuredGrid> grid = controlLevelGrid();
    vtkNew<vtkHexahedron> hex;
    for (int i = 0; i < 8; ++i) hex->GetPointIds()->SetId(i, i);
    grid->InsertNextCell(hex->GetCellType(), hex->GetPointIds());
    vtkNew<vtkTetSkinBindSurface> bind;
    const VtkErrorCapture errors(bind);
    bind->SetInputData(toVtkPolyData(bunnySurface()));
    bind->SetControlMeshData(grid);
    bind->Update();
    EXPECT_NE(
        errors.message().find("input 1 (control mesh): cell " +
                              std::to_string(grid->GetNumberOfCells() - 1) + " is a vtkHexahedron"),
        std::string::npos)
        << errors.message();
    EXPECT_EQ(bind->GetOutput()->GetNumberOfPoints(), 0);
  }
  {  // a surface point that is not a number
    const vtkSmartPointer<vtkPolyData> surface = toVtkPolyData(bunnySurface());
    surface->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0, 0);
    vtkNew<vtkTetSkinBindSurface> bind;
    const VtkErrorCapture errors(bind);
    bind->SetInputData(surface);
    bind->SetControlMeshData(controlLevelGrid());
    bind->Update();
    EXPECT_NE(errors.message().find("input 0 (surface): point 5"), std::string::npos)
        << errors.message();
    EXPECT_EQ(bind->GetOutput()->GetNumberOfPoints(), 0);
  }
  {  // points but no triangles (no points at all is an empty piece: PiecesTest.cpp)
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    empty->SetPoints(points);
    vtkNew<vtkTetSkinBindSurface> bind;
    const VtkErrorCapture errors(bind);
    bind->SetInputData(empty);
    bind->SetControlMeshData(controlLevelGrid());
    bind->Update();
    EXPECT_NE(errors.message().find("input 0 (surface): contains no triangles"), std::string::npos)
        << errors.message();
  }
}

}  // namespace
}  // namespace tetskin::test
