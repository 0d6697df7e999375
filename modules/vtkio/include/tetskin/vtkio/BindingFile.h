// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A bound surface as one .vtp file that ParaView opens: the surface at rest
// with point arrays ControlIds (3 ints, 4 for embed), Weights (3 or 4),
// Distance, MinBarycentric, FaceId and Normals, and field data naming the
// dataset, level, method and offset mode.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <optional>
#include <string>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

class vtkPolyData;

namespace tetskin {

struct BoundSurface {
  SurfaceMesh surface;  // rest positions, triangles (normals if stored)
  SurfaceBinding binding;
  std::string dataset;  // the dataset config the ids refer to, as written
};

// The binding's point arrays (ControlIds, Weights, Distance, MinBarycentric,
// FaceId) and field data (Method, Offset, Level) added to `data`, whose
// points are the bound vertices; and read back, checked for presence and
// size (not against a mesh: validateBinding). Errors name `source`.
void addBindingArrays(vtkPolyData* data, const SurfaceBinding& binding);
SurfaceBinding bindingArraysFromPolyData(vtkPolyData* data, const std::string& source);

// The surface (with `surface.normals` if present) plus the binding arrays
// and the field data 'Dataset'.
vtkSmartPointer<vtkPolyData> bindingToPolyData(const BoundSurface& bound);
BoundSurface bindingFromPolyData(vtkPolyData* data, const std::string& sourceName);
// The same, checked against `dataset` as readBinding(path, dataset) checks.
BoundSurface bindingFromPolyData(vtkPolyData* data, const std::string& sourceName,
                                 const MultiLevelTetMesh& dataset);
// Whether `data` carries a binding's field data (a .vtp from `tetskin bind`
// rather than a plain surface); bindingFromPolyData still checks the rest.
bool isBinding(vtkPolyData* data);

void writeBinding(const std::filesystem::path& path, const BoundSurface& bound);
BoundSurface readBinding(const std::filesystem::path& path);
// Reads a binding to use with `dataset`, checked against it: its level
// exists, every vertex is bound to nodes of that level, with finite
// weights summing to 1 (validateBinding). Errors name `path`.
BoundSurface readBinding(const std::filesystem::path& path, const MultiLevelTetMesh& dataset);

// A surface file as the applications open it: a .vtp with a binding's field
// data (isBinding) gives its surface and binding, checked against `dataset`
// as readBinding checks; any other surface file (.obj, .ply, .stl, a plain
// .vtp: readSurface) its surface alone. A .vtp is read once.
struct SurfaceOrBinding {
  SurfaceMesh surface;
  std::optional<SurfaceBinding> binding;
};
SurfaceOrBinding readSurfaceOrBinding(const std::filesystem::path& path,
                                      const MultiLevelTetMesh& dataset);

}  // namespace tetskin
