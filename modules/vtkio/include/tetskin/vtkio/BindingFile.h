// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A bound surface as one .vtp file that ParaView opens: the surface with
// point arrays ControlIds (3 ints, 4 for embed), Weights (3 or 4),
// Distance, MinBarycentric, FaceId and Normals, and field data naming the
// dataset, level, method, offset mode and pose. Pose "rest": the points are
// the surface as it was bound. Pose "deformed" (deform's output, simulate's
// frames, the GUI's export): the points and Normals are the moved surface,
// and a point array Displacement holds points minus rest, so the file is
// still a whole binding (its rest shape, which the displacement offset
// reads, is points - Displacement) and ParaView can warp or colour by it.
// (Files without a pose, from before it was written, read as rest.)

#include <vtkSmartPointer.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/SurfacePieces.h"
#include "tetskin/core/TetMesh.h"

class vtkDoubleArray;
class vtkPolyData;

namespace tetskin {

// A named value per surface vertex, written with a deformed surface as a
// point array (the stress carried to the skin, compare's errors).
struct PointScalars {
  std::string name;
  Eigen::VectorXd values;
};

// A named vector per surface vertex (the skin's contact forces).
struct PointVectors {
  std::string name;
  Points3 values;
};

// Where a binding has moved its surface, and what else its file shows of
// that state (not read back: the file's points and normals are the state).
struct DeformedState {
  Points3 positions, normals;
  std::vector<PointScalars> scalars = {};
  std::vector<PointVectors> vectors = {};
};

struct BoundSurface {
  SurfaceMesh surface;  // rest positions, triangles (normals if stored)
  SurfaceBinding binding;
  // The dataset config the ids refer to. In memory and from readBinding, a
  // path from the working folder; in a file (field data Dataset), the path
  // from the file's folder, so that the two can move together
  // (writeBinding and readBinding convert: datasetField, datasetOfField).
  std::string dataset;
  // A moved state, written as the file's points and normals (Pose
  // "deformed"); none for a binding at rest.
  std::optional<DeformedState> deformed;
};

// The binding's point arrays (ControlIds, Weights, Distance, MinBarycentric,
// FaceId) and field data (Method, Offset, Level, Pose "rest") added to
// `data`, whose points are the bound vertices at rest; and read back,
// checked for presence and size (not against a mesh: validateBinding).
// Errors name `source`.
void addBindingArrays(vtkPolyData* data, const SurfaceBinding& binding);
SurfaceBinding bindingArraysFromPolyData(vtkPolyData* data, const std::string& source);

// Marks `data`, a binding's arrays on moved points, as deformed: field data
// Pose "deformed", and `displacement` (points minus rest, one 3-vector per
// point) added to its point arrays as Displacement.
void markDeformed(vtkPolyData* data, vtkDoubleArray* displacement);
// Whether `data` is marked deformed. Throws Error naming `source` for a Pose
// other than rest or deformed.
bool isDeformed(vtkPolyData* data, const std::string& source);
// The bound vertices at rest: the points of `data`, less its Displacement
// array where it is deformed (an error naming `source` where that is
// missing or malformed).
Points3 restPoints(vtkPolyData* data, const std::string& source);

// The surface as a binding file holds it: `bound.surface`, or with the
// deformed state's positions and normals where there is one (an Error
// where its vertex count is not the surface's).
SurfaceMesh shownSurface(const BoundSurface& bound);

// The surface (with `surface.normals` if present; the deformed state's
// points and normals, with its Displacement, if any) plus the binding
// arrays and the field data 'Dataset'. Read back, a deformed file gives the
// rest surface without normals, and the deformed state.
vtkSmartPointer<vtkPolyData> bindingToPolyData(const BoundSurface& bound);
BoundSurface bindingFromPolyData(vtkPolyData* data, const std::string& sourceName);
// The same for `data` read from the file at `path`: its Dataset resolved
// from the file's folder (datasetOfField), as readBinding gives it.
BoundSurface bindingFromFile(vtkPolyData* data, const std::filesystem::path& path);
// Checks `binding` (of a surface of `surfaceVertices` vertices) against
// `dataset` as readBinding(path, dataset) does; an Error naming
// `sourceName` if it does not fit.
void checkBindingFits(const SurfaceBinding& binding, Index surfaceVertices,
                      const MultiLevelTetMesh& dataset, const std::string& sourceName);
inline void checkBindingFits(const BoundSurface& bound, const MultiLevelTetMesh& dataset,
                             const std::string& sourceName) {
  checkBindingFits(bound.binding, bound.surface.vertexCount(), dataset, sourceName);
}
// Whether `data` carries a binding's field data (a .vtp from `tetskin bind`
// rather than a plain surface); bindingFromPolyData still checks the rest.
bool isBinding(vtkPolyData* data);

// A binding file's Dataset field for `dataset` (a path from the working
// folder) in a file written to `file`: the path from the file's folder
// ("" stays ""). And back: the dataset a file at `file` names by `field`.
std::string datasetField(const std::filesystem::path& dataset, const std::filesystem::path& file);
std::string datasetOfField(const std::string& field, const std::filesystem::path& file);

// Writes and reads a binding file, converting its Dataset (datasetField).
// A .pvtp is written in one piece, and read whole (PartitionedSurface.h).
void writeBinding(const std::filesystem::path& path, const BoundSurface& bound);
// Writes a binding in `pieces` (from restPieces) to the .pvtp `path`.
void writeBinding(const std::filesystem::path& path, const BoundSurface& bound,
                  const std::vector<SurfacePiece>& pieces);
// `count` compact pieces of the bound surface at rest, so that every frame
// of a run is cut the same way (a rank reading piece k of each frame
// follows the same part of the body).
std::vector<SurfacePiece> restPieces(const BoundSurface& bound, int count);
BoundSurface readBinding(const std::filesystem::path& path);
// Reads a binding to use with `dataset`, checked against it: its level
// exists, every vertex is bound to nodes of that level, with finite
// weights summing to 1 (validateBinding). Errors name `path`.
BoundSurface readBinding(const std::filesystem::path& path, const MultiLevelTetMesh& dataset);

// A surface file as the applications open it: a .vtp with a binding's field
// data (isBinding) gives its surface, binding and the dataset it names
// (from the working folder); any other surface file (.obj, .ply, .stl, a
// plain .vtp: readSurface) its surface alone. A .vtp is read once. With
// `dataset`, the binding is checked against it as readBinding checks (the
// GUI reads first, to open the binding's own dataset, and checks after).
struct SurfaceOrBinding {
  SurfaceMesh surface;
  std::optional<SurfaceBinding> binding;
  std::string dataset;  // the binding's; "" for a plain surface
};
SurfaceOrBinding readSurfaceOrBinding(const std::filesystem::path& path);
SurfaceOrBinding readSurfaceOrBinding(const std::filesystem::path& path,
                                      const MultiLevelTetMesh& dataset);

}  // namespace tetskin
