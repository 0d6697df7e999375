// SPDX-License-Identifier: AGPL-3.0-or-later
#include <array>
#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/meshing/Meshers.h"

#ifdef TETSKIN_HAVE_NETGEN
namespace nglib {
#include <nglib.h>
}
#endif

namespace tetskin {

const char* netgenFinenessName(NetgenFineness fineness) {
  static const char* names[] = {"very coarse", "coarse", "moderate", "fine", "very fine"};
  return names[static_cast<int>(fineness)];
}

#ifdef TETSKIN_HAVE_NETGEN

bool netgenAvailable() {
  return true;
}

TetMesh tetrahedralizeWithNetgen(const SurfaceMesh& surface, NetgenFineness fineness,
                                 double maxEdge) {
  using namespace nglib;
  if (!(maxEdge >= 0.0) || !std::isfinite(maxEdge))
    throw Error("the Netgen element size bound must be a finite number >= 0, got " +
                formatNumber(maxEdge));
  // Netgen's GUI presets (ng/menustat.tcl): curvature safety, segments per
  // edge, grading, from very coarse to very fine. Through nglib's STL path
  // these alone barely change the mesh (its size follows maxh), so each preset
  // also bounds the element size by a fraction of the object's diagonal.
  struct Preset {
    double fineness, curvature, segments, grading, maxhFraction;
  };
  static constexpr std::array<Preset, 5> presets = {{{0.0, 1.0, 0.3, 0.7, 0.25},
                                                     {0.25, 1.5, 0.5, 0.5, 0.15},
                                                     {0.5, 2.0, 1.0, 0.3, 0.10},
                                                     {0.75, 3.0, 2.0, 0.2, 0.06},
                                                     {1.0, 5.0, 3.0, 0.1, 0.04}}};
  const Preset& preset = presets[static_cast<std::size_t>(fineness)];
  Ng_Init();
  struct Exit {
    ~Exit() { Ng_Exit(); }
  } exitGuard;
  Ng_STL_Geometry* geometry = Ng_STL_NewGeometry();
  for (Index t = 0; t < surface.triangleCount(); ++t) {
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) corners[k][c] = surface.positions(surface.triangles(t, k), c);
    Ng_STL_AddTriangle(geometry, corners[0].data(), corners[1].data(), corners[2].data());
  }
  if (Ng_STL_InitSTLGeometry(geometry) != NG_OK) throw Error("Netgen rejected the STL geometry");
  Ng_Meshing_Parameters mp;
  mp.maxh = maxEdge > 0.0 ? maxEdge : preset.maxhFraction * boundingBox(surface).diagonal();
  mp.fineness = preset.fineness;
  mp.grading = preset.grading;
  mp.elementsperedge = preset.segments;
  mp.elementspercurve = preset.curvature;
  mp.second_order = 0;
  Ng_Mesh* mesh = Ng_NewMesh();
  struct Delete {
    Ng_Mesh* m;
    ~Delete() { Ng_DeleteMesh(m); }
  } deleteGuard{mesh};
  if (Ng_STL_MakeEdges(geometry, mesh, &mp) != NG_OK) throw Error("Netgen could not find edges");
  if (Ng_STL_GenerateSurfaceMesh(geometry, mesh, &mp) != NG_OK)
    throw Error("Netgen could not mesh the surface");
  if (Ng_GenerateVolumeMesh(mesh, &mp) != NG_OK) throw Error("Netgen could not mesh the volume");
  TetMesh out;
  const int np = Ng_GetNP(mesh), ne = Ng_GetNE(mesh);
  if (ne <= 0) throw Error("Netgen produced no tetrahedra");
  out.nodes.resize(np, 3);
  for (int v = 0; v < np; ++v) {
    double x[3];
    Ng_GetPoint(mesh, v + 1, x);
    out.nodes.row(v) << x[0], x[1], x[2];
  }
  out.elements.resize(ne, 4);
  for (int e = 0; e < ne; ++e) {
    int ids[10];
    if (Ng_GetVolumeElement(mesh, e + 1, ids) != NG_TET)
      throw Error("Netgen produced a non-tetrahedral element");
    for (int k = 0; k < 4; ++k) out.elements(e, k) = ids[k] - 1;
  }
  orientElementsPositively(out);
  return out;
}

#else

bool netgenAvailable() {
  return false;
}

TetMesh tetrahedralizeWithNetgen(const SurfaceMesh&, NetgenFineness, double) {
  throw Error("this TetSkin was built without Netgen (TETSKIN_WITH_NETGEN=OFF)");
}

#endif

}  // namespace tetskin
