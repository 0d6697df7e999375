// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Surface deformation as a VTK filter (the kernel is SurfaceDeformer, report
// sections 4.1-4.2): a bound surface follows a deformed control mesh.
//
// Input 0: a bound surface: the output of vtkTetSkinBindSurface or a .vtp
// written by `tetskin bind` (the surface at rest with the binding's arrays);
// or a deformed one (this filter's output, a frame of `tetskin simulate`),
// taken at its rest shape, points - Displacement.
// Input 1: the control mesh, deformed (any vtkPointSet: its points are the
// node positions, e.g. a frame of `tetskin simulate`). ControlIds minus
// ControlIdOffset are point ids of input 1.
// Output: input 0 with the deformed points and their smooth unit normals
// (the active normals, "Normals"), the point array "Displacement" (points
// minus rest) and field data Pose "deformed" (BindingFile.h); its other
// arrays are passed on.
// The displacement offset needs the control mesh at rest too: from the
// optional input 2 (a vtkPointSet numbered as input 1), otherwise from
// input 1's point array "Displacement" (rest = points - Displacement, as
// `tetskin simulate` writes it).
// Bad input (missing or malformed binding arrays, an id that is no point of
// input 1, weights not summing to 1) is a vtkErrorMacro naming the input
// and the vertex, and an empty output.
// Time: the output has input 1's time steps (a time series of control
// meshes, such as a simulate run's frames, makes a deforming surface);
// input 0's only where input 1 has none.
// Per frame only input 1's points are read: what the filter derives from
// input 0 (the surface, the binding, its checks, the deformer's records) is
// kept until input 0, ControlIdOffset or input 1's point count changes, and
// the displacement offset's shifts until the rest positions do. The output's
// points, normals and displacement are the last update's arrays written again where
// nothing else holds them; a consumer holding an earlier output (a cache, a
// shallow copy) keeps its values, and the filter makes new arrays then.
// Distributed (ParaView's pvserver, pvbatch under MPI): input 0 arrives in
// the rank's piece and is deformed there (an empty piece gives an empty
// output with the same arrays); inputs 1 and 2 are asked for whole on every
// rank. A vertex's position depends on it alone; its normal on the
// triangles around it in its piece, so at a piece's border (without ghost
// cells: ParaView 5.11 makes none for surfaces) it is the piece's normal.

#include <vtkPolyDataAlgorithm.h>

#include <memory>

class vtkAlgorithmOutput;
class vtkPointSet;

class vtkTetSkinDeformSurface : public vtkPolyDataAlgorithm {
 public:
  static vtkTetSkinDeformSurface* New();
  vtkTypeMacro(vtkTetSkinDeformSurface, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The deformed control mesh: input port 1.
  void SetControlMeshConnection(vtkAlgorithmOutput* output);
  void SetControlMeshData(vtkPointSet* points);
  // The control mesh at rest (displacement offset only): input port 2.
  void SetRestControlMeshConnection(vtkAlgorithmOutput* output);
  void SetRestControlMeshData(vtkPointSet* points);

  // Subtracted from ControlIds to give point ids of input 1. A binding from
  // `tetskin bind` numbers nodes as the dataset does; a frame of `tetskin
  // simulate` (or a level from `tetskin convert`) numbers them from 0 within
  // its level: set this to the level's first node, the sum of the node
  // counts of the levels below it (`tetskin info DATASET.json` lists
  // them). Default 0.
  vtkSetClampMacro(ControlIdOffset, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(ControlIdOffset, vtkIdType);

 protected:
  vtkTetSkinDeformSurface();
  ~vtkTetSkinDeformSurface() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputs,
                         vtkInformationVector* output) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputs,
                          vtkInformationVector* output) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputs,
                  vtkInformationVector* output) override;

 private:
  vtkTetSkinDeformSurface(const vtkTetSkinDeformSurface&) = delete;
  void operator=(const vtkTetSkinDeformSurface&) = delete;
  vtkIdType ControlIdOffset = 0;
  struct Derived;  // what is kept from input 0 between updates
  std::unique_ptr<Derived> Kept;
};
