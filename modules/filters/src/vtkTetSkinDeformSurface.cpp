// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/filters/vtkTetSkinDeformSurface.h"

#include <vtkAlgorithmOutput.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <exception>
#include <optional>

#include "WholeInput.h"
#include "tetskin/core/ArrayNames.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkConversion.h"

vtkStandardNewMacro(vtkTetSkinDeformSurface);

namespace {

constexpr const char* kBound = "input 0 (bound surface)";
constexpr const char* kControl = "input 1 (control mesh)";
constexpr const char* kRest = "input 2 (control mesh at rest)";

// What the displacement offset needs: the control nodes at rest, from input
// 2 or from input 1's Displacement array.
tetskin::Points3 restPositions(vtkPointSet* control, vtkPointSet* rest,
                               const tetskin::Points3& deformed) {
  using tetskin::Error;
  if (rest) {
    tetskin::Points3 points = tetskin::fromVtkPoints(rest->GetPoints(), kRest);
    if (points.rows() != deformed.rows())
      throw Error(kRest, 0,
                  "has " + std::to_string(points.rows()) + " points, input 1 has " +
                      std::to_string(deformed.rows()));
    return points;
  }
  vtkDataArray* d = control->GetPointData()->GetArray(tetskin::arrays::kDisplacement);
  if (!d)
    throw Error(kControl, 0,
                "the displacement offset needs the control mesh at rest: connect it to input 2, "
                "or give input 1 a point array 'Displacement'");
  const std::optional<tetskin::Points3> displacement = tetskin::fromVtkVectors(d);
  if (!displacement || displacement->rows() != deformed.rows())
    throw Error(kControl, 0, "point array 'Displacement' is not one 3-vector per point");
  return deformed - *displacement;
}

// Whether the displacement offset's shifts made from `kept` serve `rest`:
// the same positions to within rounding (rest positions taken from a
// Displacement array, points - Displacement, differ from frame to frame in
// the last bits), 1e-10 of the largest coordinate.
bool sameRest(const tetskin::Points3& rest, const tetskin::Points3& kept) {
  if (rest.rows() != kept.rows()) return false;
  if (rest.size() == 0) return true;
  const double scale = std::max(rest.cwiseAbs().maxCoeff(), kept.cwiseAbs().maxCoeff());
  return (rest - kept).cwiseAbs().maxCoeff() <= 1e-10 * scale;
}

}  // namespace

struct vtkTetSkinDeformSurface::Derived {
  const vtkPolyData* bound = nullptr;  // identity only, with its time
  vtkMTimeType boundTime = 0;
  vtkIdType controlIdOffset = 0;
  tetskin::SurfaceMesh surface;
  tetskin::SurfaceBinding binding;           // ids minus controlIdOffset
  tetskin::Index deformerControlCount = -1;  // the deformer (and its checks) were made for it
  tetskin::Points3 rest;                     // the deformer's shifts came from it
  std::optional<tetskin::SurfaceDeformer> deformer;
  // The last update's output arrays. The next update writes into them again
  // when nothing else holds them any more: new ones each update cost their
  // allocation and page faults (about 11 ms at 1M vertices).
  vtkSmartPointer<vtkDoubleArray> positions, normals, displacement;
};

namespace {

// `array` as n x 3, written in place where only the filter holds it (a
// consumer holding the last output keeps what it was given), else new.
void makeWritable(vtkSmartPointer<vtkDoubleArray>& array, vtkIdType n) {
  if (array && array->GetReferenceCount() == 1 && array->GetNumberOfTuples() == n) {
    array->Modified();
    return;
  }
  array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(n);
}

}  // namespace

vtkTetSkinDeformSurface::vtkTetSkinDeformSurface() {
  SetNumberOfInputPorts(3);
}

vtkTetSkinDeformSurface::~vtkTetSkinDeformSurface() = default;

void vtkTetSkinDeformSurface::SetControlMeshConnection(vtkAlgorithmOutput* output) {
  SetInputConnection(1, output);
}
void vtkTetSkinDeformSurface::SetControlMeshData(vtkPointSet* points) {
  SetInputData(1, points);
}
void vtkTetSkinDeformSurface::SetRestControlMeshConnection(vtkAlgorithmOutput* output) {
  SetInputConnection(2, output);
}
void vtkTetSkinDeformSurface::SetRestControlMeshData(vtkPointSet* points) {
  SetInputData(2, points);
}

int vtkTetSkinDeformSurface::FillInputPortInformation(int port, vtkInformation* info) {
  if (port == 0) return Superclass::FillInputPortInformation(port, info);
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  if (port == 2) info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkTetSkinDeformSurface::RequestInformation(vtkInformation*, vtkInformationVector** inputs,
                                                vtkInformationVector* outputs) {
  // The pipeline's default gives the output input 0's time steps only; the
  // bound surface is static, so a time series of control meshes on input 1
  // would be asked for its first frame alone, and a change of time would
  // not run this filter again.
  vtkInformation* control = inputs[1]->GetInformationObject(0);
  vtkInformation* out = outputs->GetInformationObject(0);
  if (control && control->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())) {
    out->CopyEntry(control, vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    out->CopyEntry(control, vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  return 1;
}

int vtkTetSkinDeformSurface::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputs,
                                                 vtkInformationVector*) {
  tetskin::filters::requestWholeInput(inputs[1]);
  tetskin::filters::requestWholeInput(inputs[2]);
  return 1;
}

int vtkTetSkinDeformSurface::RequestData(vtkInformation*, vtkInformationVector** inputs,
                                         vtkInformationVector* outputs) {
  vtkPolyData* boundIn = vtkPolyData::GetData(inputs[0]);
  vtkPointSet* controlIn = vtkPointSet::GetData(inputs[1]);
  vtkPointSet* restIn =
      inputs[2]->GetNumberOfInformationObjects() > 0 ? vtkPointSet::GetData(inputs[2]) : nullptr;
  vtkPolyData* out = vtkPolyData::GetData(outputs);
  try {
    using namespace tetskin;
    if (boundIn->GetNumberOfPoints() == 0) {
      // A rank's empty piece of a distributed surface: the same arrays,
      // empty, so that the pieces append with them.
      Kept.reset();
      out->ShallowCopy(boundIn);
      auto normals = vtkSmartPointer<vtkDoubleArray>::New();
      normals->SetNumberOfComponents(3);
      normals->SetName(tetskin::arrays::kNormals);
      out->GetPointData()->SetNormals(normals);
      auto displacement = vtkSmartPointer<vtkDoubleArray>::New();
      displacement->SetNumberOfComponents(3);
      markDeformed(out, displacement);
      return 1;
    }
    const vtkMTimeType boundTime =
        std::max(boundIn->GetMTime(), boundIn->GetFieldData()->GetMTime());
    if (!Kept || Kept->bound != boundIn || Kept->boundTime != boundTime ||
        Kept->controlIdOffset != ControlIdOffset) {
      Kept.reset();
      auto derived = std::make_unique<Derived>();
      derived->surface = fromVtkPolyData(boundIn, kBound);
      // (A deformed surface, this filter's output or a frame of a run, is
      // taken at its rest shape: deformed again, it does not move twice.)
      derived->surface.positions = restPoints(boundIn, kBound);
      derived->binding = bindingArraysFromPolyData(boundIn, kBound);
      const int k = derived->binding.controlsPerVertex();
      derived->binding.controlIds.leftCols(k).array() -= static_cast<int>(ControlIdOffset);
      derived->bound = boundIn;
      derived->boundTime = boundTime;
      derived->controlIdOffset = ControlIdOffset;
      Kept = std::move(derived);
    }
    Derived& kept = *Kept;
    const Points3 deformed = fromVtkPoints(controlIn->GetPoints(), kControl);
    if (deformed.rows() != kept.deformerControlCount) kept.deformer.reset();
    // The deformer validates the binding against the control mesh when it
    // is made.
    const std::string bindingName =
        std::string(kBound) + " with ControlIdOffset " + std::to_string(ControlIdOffset);
    if (kept.binding.offset == OffsetMode::Displacement) {
      Points3 rest = restPositions(controlIn, restIn, deformed);
      if (kept.deformer && !sameRest(rest, kept.rest)) kept.deformer.reset();
      if (!kept.deformer) {
        kept.deformer.emplace(kept.surface, kept.binding, rest, bindingName);
        kept.rest = std::move(rest);
      }
    } else if (!kept.deformer) {
      // The normal offset reads no rest positions.
      kept.deformer.emplace(kept.surface, kept.binding, deformed, bindingName);
    }
    kept.deformerControlCount = deformed.rows();
    // The output lets go of the last update's arrays first, so that they are
    // written again where nothing else holds them; the kernel writes into
    // their buffers.
    out->ShallowCopy(boundIn);
    const Index n = kept.deformer->vertexCount();
    makeWritable(kept.positions, n);
    makeWritable(kept.normals, n);
    kept.deformer->deform(deformed, vectorRows(kept.positions), vectorRows(kept.normals));
    kept.normals->SetName(tetskin::arrays::kNormals);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(kept.positions);
    out->SetPoints(points);
    out->GetPointData()->SetNormals(kept.normals);
    makeWritable(kept.displacement, n);
    vectorRows(kept.displacement) = vectorRows(kept.positions) - kept.surface.positions;
    // (Into the output's own lists: ShallowCopy copied them, the input keeps its own.)
    markDeformed(out, kept.displacement);
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    Kept.reset();
    out->Initialize();
    return 0;
  }
  return 1;
}

void vtkTetSkinDeformSurface::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "ControlIdOffset: " << ControlIdOffset << "\n";
}
