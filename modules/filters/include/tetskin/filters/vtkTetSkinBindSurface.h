// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Binding as a VTK filter (the kernel is bindSurface, report section 3), so
// it composes with readers, sources and other filters in any pipeline.
//
// Input 0: the surface (vtkPolyData; polygons are triangulated for the
// search, vertices, lines and strips ignored). Input 1: the control mesh
// (vtkUnstructuredGrid of linear tetrahedra at rest, e.g. a dataset level
// from `tetskin convert DATASET.json LEVEL.vtu --level K`).
// Output: input 0 as it is (points, cells and arrays) plus the binding's
// point arrays as `tetskin bind` writes them: ControlIds (point ids of input
// 1; 3 per vertex, 4 for Embed), Weights, Distance, MinBarycentric, FaceId
// (the boundary face; for Embed the cell id of input 1), and field data
// Method, Offset and Level (0: input 1 is one level).
// vtkTetSkinDeformSurface applies it. Bad input (no triangles, a cell that
// is not a tetrahedron, a non-finite coordinate, no usable boundary face)
// is a vtkErrorMacro naming the input and the element, and an empty output.
//
// Distributed (ParaView's pvserver, pvbatch under MPI): input 0 arrives in
// the rank's piece and is bound there (an empty piece gives an empty output
// with the same arrays); input 1 is asked for whole on every rank.

#include <vtkPolyDataAlgorithm.h>

class vtkAlgorithmOutput;
class vtkUnstructuredGrid;

class vtkTetSkinBindSurface : public vtkPolyDataAlgorithm {
 public:
  static vtkTetSkinBindSurface* New();
  vtkTypeMacro(vtkTetSkinBindSurface, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods { CLOSEST = 0, SEED = 1, EMBED = 2 };
  enum OffsetModes { NORMAL = 0, DISPLACEMENT = 1 };

  // The control mesh: input port 1.
  void SetControlMeshConnection(vtkAlgorithmOutput* output);
  void SetControlMeshData(vtkUnstructuredGrid* grid);

  // closest (default), seed (the report's) or embed (containing tetrahedron).
  vtkSetClampMacro(Method, int, CLOSEST, EMBED);
  vtkGetMacro(Method, int);
  void SetMethodToClosest() { SetMethod(CLOSEST); }
  void SetMethodToSeed() { SetMethod(SEED); }
  void SetMethodToEmbed() { SetMethod(EMBED); }

  // normal (default: exact under rigid motion) or displacement (the
  // report's formula 4.1). Either deforms an embed binding alike (no offset
  // there): ParaView hides it when Method is embed.
  vtkSetClampMacro(OffsetMode, int, NORMAL, DISPLACEMENT);
  vtkGetMacro(OffsetMode, int);
  void SetOffsetModeToNormal() { SetOffsetMode(NORMAL); }
  void SetOffsetModeToDisplacement() { SetOffsetMode(DISPLACEMENT); }

  // Closest: faces within this share of the control mesh's bounding-box
  // diagonal of the nearest count as equally near (BindingOptions).
  vtkSetClampMacro(TieTolerance, double, 0.0, 1.0);
  vtkGetMacro(TieTolerance, double);

 protected:
  vtkTetSkinBindSurface();
  ~vtkTetSkinBindSurface() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputs,
                          vtkInformationVector* output) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputs,
                  vtkInformationVector* output) override;

 private:
  vtkTetSkinBindSurface(const vtkTetSkinBindSurface&) = delete;
  void operator=(const vtkTetSkinBindSurface&) = delete;
  int Method = CLOSEST;
  int OffsetMode = NORMAL;
  double TieTolerance = 1e-6;
};
