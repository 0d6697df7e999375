// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small synthetic meshes shared by the test suites.
#include <array>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::test {

// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), positively oriented.
TetMesh unitTetrahedron();

// A box [0,size] split into nx*ny*nz cubes of 6 positive tetrahedra each.
TetMesh tetGrid(int nx, int ny, int nz, const Eigen::Vector3d& size);

// A face two elements of `mesh` share (none on its boundary); throws
// std::runtime_error for a mesh without one.
std::array<int, 3> innerFace(const TetMesh& mesh);

// Closed axis-aligned box, 8 vertices, 12 outward triangles.
SurfaceMesh box(const Eigen::Vector3d& min, const Eigen::Vector3d& max);
// Closed UV sphere wound outward: `rings` bands from pole to pole,
// `segments` around.
SurfaceMesh sphere(const Eigen::Vector3d& center, double radius, int rings = 16, int segments = 24);
// Concatenates two surfaces (vertex ids of b shifted).
SurfaceMesh merge(const SurfaceMesh& a, const SurfaceMesh& b);
// Every triangle with vertices of its own (a "triangle soup" as STL gives).
SurfaceMesh soup(const SurfaceMesh& mesh);

}  // namespace tetskin::test
