// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Adapters between TetSkin's plain meshes and VTK data objects, so kernels stay
// free of VTK while pipelines, writers and renderers get VTK types.

#include <vtkSmartPointer.h>

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

class vtkDataArray;
class vtkDoubleArray;
class vtkMatrix4x4;
class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace tetskin {

// A box as VTK's bounds: xmin, xmax, ymin, ymax, zmin, zmax (for cameras
// and renderers: `.data()` where they take `const double[6]`).
inline std::array<double, 6> toVtkBounds(const BoundingBox& box) {
  return {box.min.x(), box.max.x(), box.min.y(), box.max.y(), box.min.z(), box.max.z()};
}

// Rows as double points, and back: the way back throws Error naming
// `sourceName` and the point when a coordinate is not finite; no points
// (nullptr) give an empty matrix.
vtkSmartPointer<vtkPoints> toVtkPoints(const Points3& points);
Points3 fromVtkPoints(vtkPoints* points, const std::string& sourceName);

// Rows as a named 3-component double array (normals, displacements).
vtkSmartPointer<vtkDoubleArray> toVtkVectors(const char* name, const Points3& values);
// Values as a named 1-component double array (stresses, errors).
vtkSmartPointer<vtkDoubleArray> toVtkScalars(const char* name, const Eigen::VectorXd& values);
// An affine map as VTK's 4x4 matrix (an actor's user matrix, a widget's
// transform).
vtkSmartPointer<vtkMatrix4x4> toVtkMatrix(const Eigen::Affine3d& map);
// The other way without a copy: a 3-component double array's buffer seen as
// rows, one per tuple, for a kernel to write in place (Points3Ref). Throws
// Error for a null array or another component count.
Eigen::Map<Points3> vectorRows(vtkDoubleArray* array);
// A copy of a 3-component array of any value type as rows, one per tuple
// (a Displacement or Velocity array read from a file); nullopt for a null
// array or another component count, which each caller reports in its words.
std::optional<Points3> fromVtkVectors(vtkDataArray* array);

// Triangles as polys; normals become the active point normals ("Normals"),
// texture coordinates the active TCoords ("TCoords").
vtkSmartPointer<vtkPolyData> toVtkPolyData(const SurfaceMesh& mesh);

// Polygons are triangulated; vertices, lines and strips are ignored. Active
// point normals and 2-component TCoords are kept. Throws Error naming
// `sourceName` when there are no triangles or a coordinate is not finite.
SurfaceMesh fromVtkPolyData(vtkPolyData* polyData, const std::string& sourceName);

// Linear tetrahedra as VTK_TETRA cells.
vtkSmartPointer<vtkUnstructuredGrid> toVtkUnstructuredGrid(const TetMesh& mesh);

// Requires every cell to be a VTK_TETRA; throws Error naming the first other cell.
TetMesh fromVtkUnstructuredGrid(vtkUnstructuredGrid* grid, const std::string& sourceName);

// The linear tetrahedra of a mesh made elsewhere (Gmsh through meshio,
// ParaView, another mesher): the cells of lower dimension such files carry
// (boundary triangles, edges, vertices) are left out and counted; any other
// cell of three dimensions is an error naming it. Every point stays.
struct ImportedTetrahedra {
  TetMesh mesh;
  Index skippedCells = 0;    // of dimension 0 to 2
  std::vector<Index> cells;  // each element's cell number in the file, for messages
};
ImportedTetrahedra tetrahedraOf(vtkUnstructuredGrid* grid, const std::string& sourceName);

}  // namespace tetskin
