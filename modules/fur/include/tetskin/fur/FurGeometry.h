// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Fur geometry as plain data: "fur vertices", each a vertex of the (unsplit)
// surface it grows from and a height above it, with fur texture coordinates.
//  - shells: copies of the box-textured surface at given heights, stacked
//    shell after shell from the inside out (the blending order);
//  - fins (Lengyel et al. 2001): one quad per surface edge, standing on the
//    edge along the normals, textured with a row of the fur texture seen from
//    the side; the shader fades them in only near the silhouette.
// fur-cpu evaluates every fur vertex each frame (furPoints); fur-gpu uploads
// the same attributes once and evaluates them in the vertex shader.

#include <vector>

#include "tetskin/fur/BoxTexcoords.h"
#include "tetskin/fur/FurDynamics.h"

namespace tetskin {

struct FurMesh {
  std::vector<int> source;    // per fur vertex: vertex of the unsplit surface
  std::vector<float> height;  // per fur vertex, in fur lengths (0 root, 1 tip)
  Points2 texcoords;          // per fur vertex: shells (s, t) in tiles; fins (s, row) in tiles
  Triangles triangles;
  Index vertexCount() const { return static_cast<Index>(source.size()); }
};

// One copy of `box` per entry of `heights`, in that order.
FurMesh shellMesh(const BoxTexturedSurface& box, const std::vector<float>& heights);
// `count` heights 1/count, 2/count, .., 1 (fur-cpu's shells).
std::vector<float> shellHeights(int count);

// A fin on every edge of `triangles`; `tileSize` as for box texcoords, rows
// of the texture drawn per edge from `seed`.
FurMesh finMesh(const Points3& positions, const Triangles& triangles, double tileSize,
                std::uint32_t seed);

// Positions of all fur vertices: skin point + furShellOffset (threaded).
// `normals` unit, `velocities` per surface vertex (resizes `out`).
void furPoints(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals,
               const Points3& velocities, const FurMesh& mesh, double length,
               const FurDynamicsOptions& dynamics, Points3& out);
// The same into rows owned elsewhere (e.g. the drawn vtkPoints' buffer), one
// per fur vertex (throws Error otherwise).
void furPoints(const ConstPoints3Ref& positions, const ConstPoints3Ref& normals,
               const Points3& velocities, const FurMesh& mesh, double length,
               const FurDynamicsOptions& dynamics, Points3Ref out);
// Normals of all fur vertices: each its skin vertex's (threaded), into rows
// owned elsewhere, one per fur vertex (throws Error otherwise).
void furNormals(const ConstPoints3Ref& normals, const FurMesh& mesh, Points3Ref out);

// Shells worth drawing when the fur is `furPixels` pixels tall on screen: one
// per pixel of height, within [minShells, maxShells].
int adaptiveShellCount(double furPixels, int minShells, int maxShells);

}  // namespace tetskin
