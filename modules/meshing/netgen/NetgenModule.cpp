// SPDX-License-Identifier: AGPL-3.0-or-later
// The Netgen module: nglib's STL path behind the C interface of
// NetgenModuleApi.h. Nothing of TetSkin's is linked in; errors (nglib's
// status codes and its C++ exceptions) come back as text, since no
// exception crosses the module's boundary.
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "NetgenModuleApi.h"

namespace nglib {
#include <nglib.h>
}

namespace {

char* copyText(const std::string& text) {
  char* copy = static_cast<char*>(std::malloc(text.size() + 1));
  if (copy) std::memcpy(copy, text.c_str(), text.size() + 1);
  return copy;
}

// Netgen's work: the mesh into `out`, or the first step that failed.
std::string mesh(const double* corners, std::size_t triangleCount,
                 const TetskinNetgenParameters& parameters, TetskinNetgenMesh& out) {
  using namespace nglib;
  Ng_Init();
  struct Exit {
    ~Exit() { Ng_Exit(); }
  } exitGuard;
  Ng_STL_Geometry* geometry = Ng_STL_NewGeometry();
  for (std::size_t t = 0; t < triangleCount; ++t) {
    double* c = const_cast<double*>(corners + 9 * t);  // (nglib takes non-const)
    Ng_STL_AddTriangle(geometry, c, c + 3, c + 6);
  }
  if (Ng_STL_InitSTLGeometry(geometry) != NG_OK) return "Netgen rejected the STL geometry";
  Ng_Meshing_Parameters mp;
  mp.maxh = parameters.maxh;
  mp.fineness = parameters.fineness;
  mp.grading = parameters.grading;
  mp.elementsperedge = parameters.elementsPerEdge;
  mp.elementspercurve = parameters.elementsPerCurve;
  mp.second_order = 0;
  Ng_Mesh* mesh = Ng_NewMesh();
  struct Delete {
    Ng_Mesh* m;
    ~Delete() { Ng_DeleteMesh(m); }
  } deleteGuard{mesh};
  if (Ng_STL_MakeEdges(geometry, mesh, &mp) != NG_OK) return "Netgen could not find edges";
  if (Ng_STL_GenerateSurfaceMesh(geometry, mesh, &mp) != NG_OK)
    return "Netgen could not mesh the surface";
  if (Ng_GenerateVolumeMesh(mesh, &mp) != NG_OK) return "Netgen could not mesh the volume";
  const int np = Ng_GetNP(mesh), ne = Ng_GetNE(mesh);
  if (ne <= 0) return "Netgen produced no tetrahedra";
  out.nodes = static_cast<double*>(std::malloc(sizeof(double) * 3 * static_cast<std::size_t>(np)));
  out.elements = static_cast<int*>(std::malloc(sizeof(int) * 4 * static_cast<std::size_t>(ne)));
  if (!out.nodes || !out.elements) return "out of memory for Netgen's mesh";
  out.nodeCount = np;
  out.elementCount = ne;
  for (int v = 0; v < np; ++v) Ng_GetPoint(mesh, v + 1, out.nodes + 3 * v);
  for (int e = 0; e < ne; ++e) {
    int ids[10];
    if (Ng_GetVolumeElement(mesh, e + 1, ids) != NG_TET)
      return "Netgen produced a non-tetrahedral element";
    for (int k = 0; k < 4; ++k) out.elements[4 * e + k] = ids[k] - 1;
  }
  return {};
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int tetskin_netgen_mesh(
    const double* corners, std::size_t triangleCount, const TetskinNetgenParameters* parameters,
    TetskinNetgenMesh* out) {
  *out = TetskinNetgenMesh{0, nullptr, 0, nullptr, nullptr};
  std::string error;
  try {
    error = mesh(corners, triangleCount, *parameters, *out);
  } catch (const std::exception& e) {
    error = std::string("Netgen failed: ") + e.what();
  } catch (...) {
    error = "Netgen failed";
  }
  if (error.empty()) return 0;
  tetskin_netgen_free(out);
  out->error = copyText(error);
  return 1;
}

__attribute__((visibility("default"))) void tetskin_netgen_free(TetskinNetgenMesh* mesh) {
  std::free(mesh->nodes);
  std::free(mesh->elements);
  std::free(mesh->error);
  *mesh = TetskinNetgenMesh{0, nullptr, 0, nullptr, nullptr};
}
}
