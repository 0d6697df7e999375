// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The per-frame kernel (report 4.1-4.2): deformed surface positions from the
// control-mesh state through the binding, then smooth normals. Threaded (TBB),
// allocation-free after construction, with the per-vertex binding packed into
// one contiguous record so a frame streams through memory once.

#include <string>
#include <vector>

#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/deformation/VertexNormals.h"

namespace tetskin {

class SurfaceDeformer {
 public:
  // `restSurface`: the bound surface at rest; `controlRest`: the dataset's
  // nodes at rest (dataset numbering, needed by the Displacement offset).
  // Validates the binding against both (validateBinding), naming
  // `bindingName` in the Error.
  SurfaceDeformer(const SurfaceMesh& restSurface, const SurfaceBinding& binding,
                  const Points3& controlRest, const std::string& bindingName = "binding");

  // Inputs:
  //   control    #N x 3 deformed node positions in the dataset's numbering
  //              (model units; read where they lie: a NumPy array's rows too)
  // Outputs:
  //   positions  #V x 3 deformed surface positions (model units)
  //   normals    #V x 3 unit vertex normals
  // (resized only if their size differs).
  void deform(ConstPoints3Ref control, Points3& positions, Points3& normals);
  // The same into rows owned elsewhere (a VTK array's buffer): each must have
  // vertexCount() rows, else Error.
  void deform(ConstPoints3Ref control, Points3Ref positions, Points3Ref normals);

  // Positions only (for callers that need no normals).
  void deformPositions(ConstPoints3Ref control, Points3& positions) const;
  void deformPositions(ConstPoints3Ref control, Points3Ref positions) const;

  Index vertexCount() const { return static_cast<Index>(records_.size()); }
  const Triangles& triangles() const { return triangles_; }
  // Bytes one deform() reads and writes at least (for bandwidth comparisons).
  std::size_t bytesPerFrame() const;

 private:
  struct Record {
    int ids[4];
    double w[4];
    double d;
  };
  OffsetMode offset_;
  int controls_;
  std::vector<Record> records_;
  Points3 shifts_;  // displacementShifts() (Displacement offset only)
  Triangles triangles_;
  VertexTriangleAdjacency adjacency_;
  Points3 faceScratch_;
  Index maxControlId_ = -1;
};

// The Displacement offset (report formula 4.1, x = x_rest + sum w_i (X_i -
// X_i,rest)) rearranged as x = sum w_i X_i + shift: one sum per frame, the
// same on the CPU and in the GPU paths. Per surface vertex, shift = x_rest -
// sum w_i X_i,rest; `controlRest` in dataset numbering.
Points3 displacementShifts(const SurfaceBinding& binding, const Points3& restSurface,
                           const Points3& controlRest);

// A control-mesh state in the dataset's numbering from `given` positions: all
// dataset nodes, or only those of `level` (the other nodes stay at rest).
// Throws Error naming `sourceName` when the count fits neither.
Points3 datasetPositions(const MultiLevelTetMesh& mesh, int level, const Points3& given,
                         const std::string& sourceName);

}  // namespace tetskin
