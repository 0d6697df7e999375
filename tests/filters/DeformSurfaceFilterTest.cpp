// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkUnstructuredGridAlgorithm.h>

#include <cmath>

#include "FilterTestData.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/filters/vtkTetSkinBindSurface.h"
#include "tetskin/filters/vtkTetSkinDeformSurface.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin::test {
namespace {

Points3 pointsOf(vtkPointSet* data) {
  return fromVtkPoints(data->GetPoints(), "test");
}

Points3 normalsOf(vtkPolyData* data) {
  vtkDataArray* n = data->GetPointData()->GetNormals();
  EXPECT_NE(n, nullptr);
  Points3 out(data->GetNumberOfPoints(), 3);
  for (Index i = 0; i < out.rows(); ++i)
    for (int k = 0; k < 3; ++k) out(i, k) = n ? n->GetComponent(i, k) : 0.0;
  return out;
}

// Rows of `points` moved by `transform`'s rotation only (normals) or in full.
Points3 transformed(vtkTransform* transform, const Points3& points, bool rotationOnly) {
  Points3 out(points.rows(), 3);
  for (Index i = 0; i < points.rows(); ++i) {
    double in[3] = {points(i, 0), points(i, 1), points(i, 2)}, moved[3];
    if (rotationOnly)
      transform->TransformVector(in, moved);
    else
      transform->TransformPoint(in, moved);
    for (int k = 0; k < 3; ++k) out(i, k) = moved[k];
  }
  return out;
}

double diagonal(const Points3& p) {
  return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm();
}

// A grid whose points are moved by a smooth field, with the Displacement
// array `tetskin simulate` writes.
vtkSmartPointer<vtkUnstructuredGrid> bentGrid(bool withDisplacementArray) {
  vtkSmartPointer<vtkUnstructuredGrid> grid = controlLevelGrid();
  vtkPoints* points = grid->GetPoints();
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    const double d[3] = {0.3 * std::sin(0.4 * p[1]), 0.05 * p[0] * p[2], -0.2 * std::cos(p[1])};
    displacement->SetTuple(i, d);
    points->SetPoint(i, p[0] + d[0], p[1] + d[1], p[2] + d[2]);
  }
  if (withDisplacementArray) grid->GetPointData()->AddArray(displacement);
  return grid;
}

// A time series of control meshes, as a reader of a simulate run's frames
// gives: time steps 0, 1, 2, the mesh at time t shifted by t along x.
class ShiftedControlSeries : public vtkUnstructuredGridAlgorithm {
 public:
  static ShiftedControlSeries* New();
  vtkTypeMacro(ShiftedControlSeries, vtkUnstructuredGridAlgorithm)
  static constexpr double kTimes[3] = {0.0, 1.0, 2.0};

 protected:
  ShiftedControlSeries() { SetNumberOfInputPorts(0); }
  int RequestInformation(vtkInformation*, vtkInformationVector**,
                         vtkInformationVector* outputs) override {
    vtkInformation* out = outputs->GetInformationObject(0);
    out->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), kTimes, 3);
    const double range[2] = {kTimes[0], kTimes[2]};
    out->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override {
    vtkInformation* info = outputs->GetInformationObject(0);
    const double time = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                            ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
                            : 0.0;
    vtkUnstructuredGrid* out = vtkUnstructuredGrid::GetData(outputs);
    out->DeepCopy(controlLevelGrid());
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
      double p[3];
      out->GetPoint(i, p);
      out->GetPoints()->SetPoint(i, p[0] + time, p[1], p[2]);
    }
    ++Executions;
    return 1;
  }

 public:
  int Executions = 0;
};
vtkStandardNewMacro(ShiftedControlSeries);

TEST(DeformSurfaceFilter, AsksATimeSeriesOfControlMeshesForEachTimeItIsAskedFor) {
  vtkNew<vtkTetSkinBindSurface> bind;
  bind->SetInputData(toVtkPolyData(bunnySurface()));
  bind->SetControlMeshData(controlLevelGrid());
  vtkNew<ShiftedControlSeries> series;
  vtkNew<vtkTetSkinDeformSurface> deform;
  deform->SetInputConnection(bind->GetOutputPort());
  deform->SetControlMeshConnection(series->GetOutputPort());

  // The output offers the series' time steps (the bound surface has none).
  deform->UpdateInformation();
  vtkInformation* out = deform->GetOutputInformation(0);
  ASSERT_TRUE(out->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(out->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 3);
  EXPECT_EQ(out->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[2], 2.0);

  // Each time asked for, back and forth, moves the surface with that frame.
  const Points3& rest = bunnySurface().positions;
  const double tolerance = 1e-9 * diagonal(rest);
  for (double time : {2.0, 0.0, 1.0, 2.0}) {
    SCOPED_TRACE("time " + std::to_string(time));
    ASSERT_TRUE(deform->UpdateTimeStep(time));
    const Points3 moved = pointsOf(deform->GetOutput());
    ASSERT_EQ(moved.rows(), rest.rows());
    EXPECT_LT((moved - (rest.rowwise() + Eigen::RowVector3d(time, 0, 0))).cwiseAbs().maxCoeff(),
              tolerance);
  }
  EXPECT_EQ(series->Executions, 4);
}

// bind -> deform, the control mesh moved by `motion` through a transform
// filter: a pipeline as a VTK user builds it.
struct MovedControlPipeline {
  vtkNew<vtkTetSkinBindSurface> bind;
  vtkNew<vtkTransform> motion;
  vtkNew<vtkTransformFilter> move;
  vtkNew<vtkTetSkinDeformSurface> deform;
  MovedControlPipeline() {
    bind->SetInputData(toVtkPolyData(bunnySurface()));
    bind->SetControlMeshData(controlLevelGrid());
    move->SetInputData(controlLevelGrid());
    move->SetTransform(motion);
    deform->SetInputConnection(bind->GetOutputPort());
    deform->SetControlMeshConnection(move->GetOutputPort());
  }
};

TEST(DeformSurfaceFilter, FollowsARigidMotionOfTheControlMeshThroughAPipeline) {
  MovedControlPipeline pipeline;
  vtkTransform* motion = pipeline.motion;
  vtkTetSkinDeformSurface* deform = pipeline.deform;

  deform->Update();  // at rest: the normal offset gives back the surface
  const Points3 rest = pointsOf(deform->GetOutput());
  const Points3 restNormals = normalsOf(deform->GetOutput());
  const double tolerance = 1e-9 * diagonal(rest);
  EXPECT_LT((rest - bunnySurface().positions).cwiseAbs().maxCoeff(), tolerance);
  for (Index i = 0; i < restNormals.rows(); ++i)
    ASSERT_NEAR(restNormals.row(i).norm(), 1.0, 1e-12) << "vertex " << i;

  for (double angle : {30.0, 130.0}) {  // the pipeline reruns when the transform changes
    SCOPED_TRACE("angle " + std::to_string(angle));
    motion->Identity();
    motion->Translate(1.5, -2.0, 0.25);
    motion->RotateWXYZ(angle, 0.3, 1.0, -0.2);
    deform->Update();
    EXPECT_LT(
        (pointsOf(deform->GetOutput()) - transformed(motion, rest, false)).cwiseAbs().maxCoeff(),
        tolerance);
    EXPECT_LT((normalsOf(deform->GetOutput()) - transformed(motion, restNormals, true))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-9);
  }
  // The binding arrays travel on, so a deformed surface can be inspected;
  // it says it is deformed, with its displacement from rest, and the
  // binding it came from still says rest.
  vtkPolyData* out = deform->GetOutput();
  EXPECT_NE(out->GetPointData()->GetArray("MinBarycentric"), nullptr);
  EXPECT_TRUE(isDeformed(out, "output"));
  EXPECT_LT((restPoints(out, "output") - rest).cwiseAbs().maxCoeff(), tolerance);
  EXPECT_FALSE(isDeformed(pipeline.bind->GetOutput(), "binding"));
  EXPECT_EQ(pipeline.bind->GetOutput()->GetPointData()->GetArray("Displacement"), nullptr);
}

// A deformed surface (this filter's output, a frame of a run) given to a
// deform filter is taken at its rest shape: it does not move twice. (The
// displacement offset reads the rest shape; the normal offset would not
// tell.)
TEST(DeformSurfaceFilter, ADeformedSurfaceIsDeformedFromItsRestShape) {
  MovedControlPipeline pipeline;
  pipeline.bind->SetOffsetModeToDisplacement();
  pipeline.deform->SetRestControlMeshData(controlLevelGrid());
  pipeline.motion->Translate(1, 0, 0);
  vtkNew<vtkTransform> secondMotion;
  secondMotion->Translate(0, 2, 0);
  vtkNew<vtkTransformFilter> secondMove;
  secondMove->SetInputData(controlLevelGrid());
  secondMove->SetTransform(secondMotion);
  vtkNew<vtkTetSkinDeformSurface> again;
  const VtkErrorCapture errors(again);
  again->SetInputConnection(pipeline.deform->GetOutputPort());
  again->SetControlMeshConnection(secondMove->GetOutputPort());
  again->SetRestControlMeshData(controlLevelGrid());
  again->Update();
  EXPECT_FALSE(errors.failed()) << errors.message();
  const Points3 expected = bunnySurface().positions.rowwise() + Eigen::RowVector3d(0, 2, 0);
  EXPECT_LT((pointsOf(again->GetOutput()) - expected).cwiseAbs().maxCoeff(),
            1e-9 * diagonal(expected));
}

TEST(DeformSurfaceFilter, AConsumerKeepsTheOutputItHoldsWhileUnheldArraysAreWrittenAgain) {
  MovedControlPipeline pipeline;
  vtkTransform* motion = pipeline.motion;
  vtkTetSkinDeformSurface* deform = pipeline.deform;
  auto shiftTo = [&](double x) {
    motion->Identity();
    motion->Translate(x, 0, 0);
    deform->Update();
  };

  // A consumer holds the output of x = 1 (as a cache or a shallow copy
  // downstream would): the next update must not write into its arrays.
  shiftTo(1.0);
  vtkNew<vtkPolyData> held;
  held->ShallowCopy(deform->GetOutput());
  const Points3 heldPoints = pointsOf(held), heldNormals = normalsOf(held);
  shiftTo(2.0);
  EXPECT_EQ(pointsOf(held), heldPoints);
  EXPECT_EQ(normalsOf(held), heldNormals);
  EXPECT_NE(deform->GetOutput()->GetPoints()->GetData(), held->GetPoints()->GetData());
  const Points3 atTwo = pointsOf(deform->GetOutput());
  EXPECT_LT((atTwo - (heldPoints.rowwise() + Eigen::RowVector3d(1, 0, 0))).cwiseAbs().maxCoeff(),
            1e-9 * diagonal(atTwo));

  // Held by no one, the last arrays are written again, with the new values.
  vtkDataArray* points = deform->GetOutput()->GetPoints()->GetData();
  vtkDataArray* normals = deform->GetOutput()->GetPointData()->GetNormals();
  vtkDataArray* displacement = deform->GetOutput()->GetPointData()->GetArray("Displacement");
  shiftTo(3.0);
  EXPECT_EQ(deform->GetOutput()->GetPoints()->GetData(), points);
  EXPECT_EQ(deform->GetOutput()->GetPointData()->GetNormals(), normals);
  EXPECT_EQ(deform->GetOutput()->GetPointData()->GetArray("Displacement"), displacement);
  EXPECT_LT(
      (restPoints(deform->GetOutput(), "output") - bunnySurface().positions).cwiseAbs().maxCoeff(),
      1e-9 * diagonal(atTwo));
  EXPECT_LT((pointsOf(deform->GetOutput()) - (atTwo.rowwise() + Eigen::RowVector3d(1, 0, 0)))
                .cwiseAbs()
                .maxCoeff(),
            1e-9 * diagonal(atTwo));
  EXPECT_LT((normalsOf(deform->GetOutput()) - heldNormals).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DeformSurfaceFilter, DisplacementOffsetTakesTheRestFromInputTwoOrTheDisplacementArray) {
  vtkNew<vtkTetSkinBindSurface> bind;
  bind->SetInputData(toVtkPolyData(bunnySurface()));
  bind->SetControlMeshData(controlLevelGrid());
  bind->SetOffsetModeToDisplacement();
  bind->Update();

  // The kernel on the same data.
  const SurfaceBinding binding = bindingArraysFromPolyData(bind->GetOutput(), "binding");
  const vtkSmartPointer<vtkUnstructuredGrid> rest = controlLevelGrid();
  SurfaceDeformer kernel(bunnySurface(), binding, pointsOf(rest));
  Points3 expected, expectedNormals;
  kernel.deform(pointsOf(bentGrid(true)), expected, expectedNormals);
  ASSERT_GT((expected - bunnySurface().positions).cwiseAbs().maxCoeff(), 0.1);

  {  // rest = points - Displacement
    vtkNew<vtkTetSkinDeformSurface> deform;
    deform->SetInputConnection(bind->GetOutputPort());
    deform->SetControlMeshData(bentGrid(true));
    deform->Update();
    EXPECT_LT((pointsOf(deform->GetOutput()) - expected).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((normalsOf(deform->GetOutput()) - expectedNormals).cwiseAbs().maxCoeff(), 1e-12);
  }
  {  // rest from input 2
    vtkNew<vtkTetSkinDeformSurface> deform;
    deform->SetInputConnection(bind->GetOutputPort());
    deform->SetControlMeshData(bentGrid(false));
    deform->SetRestControlMeshData(rest);
    deform->Update();
    EXPECT_LT((pointsOf(deform->GetOutput()) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
  {  // neither: an error that says what is missing
    vtkNew<vtkTetSkinDeformSurface> deform;
    const VtkErrorCapture errors(deform);
    deform->SetInputConnection(bind->GetOutputPort());
    deform->SetControlMeshData(bentGrid(false));
    deform->Update();
    EXPECT_NE(errors.message().find("the displacement offset needs the control mesh at rest"),
              std::string::npos)
        << errors.message();
    EXPECT_EQ(deform->GetOutput()->GetNumberOfPoints(), 0);
  }
}

// Points of `grid` (and its Displacement array, if any) moved by `shift`.
void translate(vtkPointSet* grid, const Eigen::RowVector3d& shift, bool displacementToo) {
  vtkPoints* points = grid->GetPoints();
  vtkDataArray* displacement = grid->GetPointData()->GetArray("Displacement");
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]);
    if (displacementToo)
      for (int k = 0; k < 3; ++k)
        displacement->SetComponent(i, k, displacement->GetComponent(i, k) + shift[k]);
  }
  points->Modified();
  if (displacementToo) displacement->Modified();
}

TEST(DeformSurfaceFilter, WhatItKeepsBetweenUpdatesFollowsChangesOfItsInputs) {
  vtkNew<vtkTetSkinBindSurface> bind;
  bind->SetInputData(toVtkPolyData(bunnySurface()));
  bind->SetControlMeshData(controlLevelGrid());
  bind->SetOffsetModeToDisplacement();
  bind->Update();
  vtkNew<vtkPolyData> bound;
  bound->DeepCopy(bind->GetOutput());
  const SurfaceBinding binding = bindingArraysFromPolyData(bound, "binding");

  // Each update against the kernel made afresh for that update's inputs.
  auto expectKernelResult = [&](vtkTetSkinDeformSurface* deform, const Points3& controlRest,
                                const char* what) {
    SCOPED_TRACE(what);
    deform->Update();
    SurfaceDeformer kernel(fromVtkPolyData(bound, "bound"), binding, controlRest);
    Points3 expected, expectedNormals;
    kernel.deform(pointsOf(vtkPointSet::SafeDownCast(deform->GetInputDataObject(1, 0))), expected,
                  expectedNormals);
    ASSERT_EQ(deform->GetOutput()->GetNumberOfPoints(), expected.rows());
    EXPECT_LT((pointsOf(deform->GetOutput()) - expected).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((normalsOf(deform->GetOutput()) - expectedNormals).cwiseAbs().maxCoeff(), 1e-12);
  };
  const Eigen::RowVector3d up(0.0, 0.0, 0.5);

  {  // rest from input 2
    const vtkSmartPointer<vtkUnstructuredGrid> control = bentGrid(false);
    const vtkSmartPointer<vtkUnstructuredGrid> rest = controlLevelGrid();
    vtkNew<vtkTetSkinDeformSurface> deform;
    deform->SetInputData(bound);
    deform->SetControlMeshData(control);
    deform->SetRestControlMeshData(rest);
    expectKernelResult(deform, pointsOf(rest), "first update");
    translate(control, up, false);
    expectKernelResult(deform, pointsOf(rest), "the control mesh moved");
    translate(rest, up, false);
    expectKernelResult(deform, pointsOf(rest), "the rest moved");
    const Points3 before = pointsOf(deform->GetOutput());
    translate(bound, up, false);  // the surface's rest positions feed the shifts
    expectKernelResult(deform, pointsOf(rest), "the bound surface moved");
    const Points3 moved = pointsOf(deform->GetOutput()) - before;
    EXPECT_LT((moved.rowwise() - up).cwiseAbs().maxCoeff(), 1e-12);
    translate(bound, -up, false);
  }
  {  // rest from the Displacement array, from frame to frame
    const vtkSmartPointer<vtkUnstructuredGrid> control = bentGrid(true);
    vtkNew<vtkTetSkinDeformSurface> deform;
    deform->SetInputData(bound);
    deform->SetControlMeshData(control);
    const Points3 rest = pointsOf(controlLevelGrid());
    expectKernelResult(deform, rest, "first frame");
    translate(control, up, true);  // the same rest, displaced further
    expectKernelResult(deform, rest, "second frame");
    translate(control, up, false);  // the rest moved: points moved, displacements not
    expectKernelResult(deform, rest.rowwise() + up, "a frame with another rest");
  }
}

TEST(DeformSurfaceFilter, TakesABindingFromTheCommandLineWithTheLevelsFirstNodeAsOffset) {
  // What `tetskin bind --level 1` writes: ids in the dataset's numbering.
  BoundSurface bound;
  bound.surface = bunnySurface();
  bound.binding = bindSurface(bunnySurface(), sampleDataset().mesh, kBoundLevel);
  bound.dataset = "bunny.json";
  const vtkSmartPointer<vtkPolyData> file = bindingToPolyData(bound);
  // A level-local frame, as `tetskin simulate` writes it, moved rigidly.
  vtkNew<vtkTransform> motion;
  motion->Translate(0.0, 3.0, -1.0);
  vtkNew<vtkTransformFilter> move;
  move->SetInputData(controlLevelGrid());
  move->SetTransform(motion);

  vtkNew<vtkTetSkinDeformSurface> deform;
  const VtkErrorCapture errors(deform);
  deform->SetInputData(file);
  deform->SetControlMeshConnection(move->GetOutputPort());
  deform->Update();  // offset 0: the dataset's ids run past the level's points
  EXPECT_NE(errors.message().find("input 0 (bound surface) with ControlIdOffset 0"),
            std::string::npos)
      << errors.message();
  EXPECT_EQ(deform->GetOutput()->GetNumberOfPoints(), 0);

  deform->SetControlIdOffset(sampleDataset().mesh.levels[kBoundLevel].firstNode);
  deform->Update();
  const Points3 moved = pointsOf(deform->GetOutput());
  ASSERT_EQ(moved.rows(), bunnySurface().vertexCount());
  EXPECT_LT((moved - transformed(motion, bunnySurface().positions, false)).cwiseAbs().maxCoeff(),
            1e-9 * diagonal(moved));
}

TEST(DeformSurfaceFilter, AMalformedBindingIsAnErrorNamingTheArray) {
  const vtkSmartPointer<vtkPolyData> plain = toVtkPolyData(bunnySurface());
  vtkNew<vtkTetSkinDeformSurface> deform;
  const VtkErrorCapture errors(deform);
  deform->SetInputData(plain);
  deform->SetControlMeshData(controlLevelGrid());
  deform->Update();
  EXPECT_NE(errors.message().find("input 0 (bound surface): is not a TetSkin binding"),
            std::string::npos)
      << errors.message();
  EXPECT_EQ(deform->GetOutput()->GetNumberOfPoints(), 0);
}

}  // namespace
}  // namespace tetskin::test
