// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/filters/vtkTetSkinBindSurface.h"

#include <vtkAlgorithmOutput.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <exception>
#include <string>

#include "WholeInput.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/binding/BindingSummary.h"
#include "tetskin/core/Error.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/VtkConversion.h"

vtkStandardNewMacro(vtkTetSkinBindSurface);

namespace {

tetskin::BindingMethod methodOf(int method) {
  using tetskin::BindingMethod;
  return method == vtkTetSkinBindSurface::SEED    ? BindingMethod::Seed
         : method == vtkTetSkinBindSurface::EMBED ? BindingMethod::Embed
                                                  : BindingMethod::Closest;
}

tetskin::OffsetMode offsetModeOf(int mode) {
  return mode == vtkTetSkinBindSurface::DISPLACEMENT ? tetskin::OffsetMode::Displacement
                                                     : tetskin::OffsetMode::Normal;
}

}  // namespace

vtkTetSkinBindSurface::vtkTetSkinBindSurface() {
  SetNumberOfInputPorts(2);
}

void vtkTetSkinBindSurface::SetControlMeshConnection(vtkAlgorithmOutput* output) {
  SetInputConnection(1, output);
}

void vtkTetSkinBindSurface::SetControlMeshData(vtkUnstructuredGrid* grid) {
  SetInputData(1, grid);
}

int vtkTetSkinBindSurface::FillInputPortInformation(int port, vtkInformation* info) {
  if (port == 0) return Superclass::FillInputPortInformation(port, info);
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

int vtkTetSkinBindSurface::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputs,
                                               vtkInformationVector*) {
  tetskin::filters::requestWholeInput(inputs[1]);
  return 1;
}

int vtkTetSkinBindSurface::RequestData(vtkInformation*, vtkInformationVector** inputs,
                                       vtkInformationVector* outputs) {
  vtkPolyData* surfaceIn = vtkPolyData::GetData(inputs[0]);
  vtkUnstructuredGrid* controlIn = vtkUnstructuredGrid::GetData(inputs[1]);
  vtkPolyData* out = vtkPolyData::GetData(outputs);
  try {
    using namespace tetskin;
    if (surfaceIn->GetNumberOfPoints() == 0) {
      // A rank's empty piece of a distributed surface: the same arrays,
      // empty, so that the pieces append with them.
      out->ShallowCopy(surfaceIn);
      SurfaceBinding empty;
      empty.method = methodOf(Method);
      empty.offset = offsetModeOf(OffsetMode);
      empty.level = 0;  // (as bound: input 1 is one level)
      addBindingArrays(out, empty);
      return 1;
    }
    const SurfaceMesh surface = fromVtkPolyData(surfaceIn, "input 0 (surface)");
    // One level: control ids are point ids of input 1.
    MultiLevelTetMesh mesh;
    appendLevel(mesh, fromVtkUnstructuredGrid(controlIn, "input 1 (control mesh)"));
    BindingOptions options;
    options.method = methodOf(Method);
    options.offset = offsetModeOf(OffsetMode);
    options.tieTolerance = TieTolerance;
    const SurfaceBinding binding = bindSurface(surface, mesh, 0, options);
    out->ShallowCopy(surfaceIn);
    addBindingArrays(out, binding);
    const BindingSummary summary = summarizeBinding(binding, boundingBox(surface).diagonal());
    if (const std::string warning =
            misfitWarning(summary, boundingBox(mesh.nodes).diagonal(), "input 1 (control mesh)");
        !warning.empty())
      vtkWarningMacro(<< warning);
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    out->Initialize();
    return 0;
  }
  return 1;
}

void vtkTetSkinBindSurface::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  const char* methods[] = {"closest", "seed", "embed"};
  os << indent << "Method: " << methods[Method] << "\n";
  os << indent << "OffsetMode: " << (OffsetMode == DISPLACEMENT ? "displacement" : "normal")
     << "\n";
  os << indent << "TieTolerance: " << TieTolerance << "\n";
}
