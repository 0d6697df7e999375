// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The C interface of the Netgen module (libtetskin_netgen.so), which alone
// links nglib. Netgen brings MPI, Python and OpenCASCADE with it: 64 more
// shared libraries and 0.15 to 0.2 s of CPU to load. TetSkin loads the module when
// a mesh is first asked of Netgen (NetgenMesher.cpp), so every other
// command starts without them.
#include <cstddef>

extern "C" {

// A run's parameters (nglib's Ng_Meshing_Parameters, as NetgenMesher.cpp
// chooses them).
struct TetskinNetgenParameters {
  double maxh;
  double fineness;
  double grading;
  double elementsPerEdge;
  double elementsPerCurve;
};

// A run's result: nodeCount x 3 coordinates and elementCount x 4 node
// indices (0-based), or an error message; free it with
// tetskin_netgen_free.
struct TetskinNetgenMesh {
  int nodeCount;
  double* nodes;
  int elementCount;
  int* elements;
  char* error;  // nullptr on success
};

// Meshes the closed surface whose triangles' corners `corners` holds
// (9 coordinates a triangle). Returns 0 on success.
int tetskin_netgen_mesh(const double* corners, std::size_t triangleCount,
                        const TetskinNetgenParameters* parameters, TetskinNetgenMesh* out);
void tetskin_netgen_free(TetskinNetgenMesh* mesh);

// The names the loader looks the functions up by.
#define TETSKIN_NETGEN_MESH "tetskin_netgen_mesh"
#define TETSKIN_NETGEN_FREE "tetskin_netgen_free"
}
