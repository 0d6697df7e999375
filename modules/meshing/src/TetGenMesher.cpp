// SPDX-License-Identifier: AGPL-3.0-or-later
#define TETLIBRARY
#include <tetgen.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tetskin/core/Error.h"
#include "tetskin/meshing/Meshers.h"
#include "tetskin/meshing/SurfaceNesting.h"

namespace tetskin {
namespace {

// TetGen throws plain ints (tetgen.h, terminatetetgen()).
std::string tetgenError(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory";
    case 2:
      return "TetGen hit an internal error";
    case 3:
      return "TetGen found self-intersecting facets";
    case 4:
      return "TetGen found a very small input feature (check the tolerance)";
    case 5:
      return "TetGen found two very close input facets";
    case 10:
      return "TetGen found an input error";
    default:
      return "TetGen failed with code " + std::to_string(code);
  }
}

}  // namespace

TetMesh tetrahedralizeWithTetGen(const SurfaceMesh& surface, double radiusEdgeRatio,
                                 double maxVolume) {
  if (!(radiusEdgeRatio > 1.0))
    throw Error("the TetGen quality (radius-edge ratio) must be greater than 1.0, got " +
                formatNumber(radiusEdgeRatio));
  if (!(maxVolume >= 0.0) || !std::isfinite(maxVolume))
    throw Error("the TetGen volume bound must be a finite number >= 0, got " +
                formatNumber(maxVolume));
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface.vertexCount());
  in.pointlist = new REAL[static_cast<std::size_t>(in.numberofpoints) * 3];
  for (Index v = 0; v < surface.vertexCount(); ++v)
    for (int k = 0; k < 3; ++k) in.pointlist[v * 3 + k] = surface.positions(v, k);
  in.numberoffacets = static_cast<int>(surface.triangleCount());
  in.facetlist = new tetgenio::facet[static_cast<std::size_t>(in.numberoffacets)];
  for (Index t = 0; t < surface.triangleCount(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) f.polygonlist[0].vertexlist[k] = surface.triangles(t, k);
  }
  // Cavities (parts wound into the void they bound) stay empty: TetGen
  // removes the region around each hole point, as it does the outside.
  const std::vector<Eigen::Vector3d> holes = cavityPoints(surface);
  in.numberofholes = static_cast<int>(holes.size());
  if (!holes.empty()) {
    in.holelist = new REAL[holes.size() * 3];
    for (std::size_t h = 0; h < holes.size(); ++h)
      for (int k = 0; k < 3; ++k) in.holelist[h * 3 + static_cast<std::size_t>(k)] = holes[h][k];
  }
  char switches[64];
  if (maxVolume > 0.0)
    std::snprintf(switches, sizeof switches, "pq%.6ga%.9gQ", radiusEdgeRatio, maxVolume);
  else
    std::snprintf(switches, sizeof switches, "pq%.6gQ", radiusEdgeRatio);
  try {
    tetrahedralize(switches, &in, &out);
  } catch (int code) {
    throw Error(tetgenError(code));
  }
  if (out.numberoftetrahedra <= 0) throw Error("TetGen produced no tetrahedra");
  TetMesh mesh;
  mesh.nodes.resize(out.numberofpoints, 3);
  for (int v = 0; v < out.numberofpoints; ++v)
    for (int k = 0; k < 3; ++k) mesh.nodes(v, k) = out.pointlist[v * 3 + k];
  mesh.elements.resize(out.numberoftetrahedra, 4);
  for (int e = 0; e < out.numberoftetrahedra; ++e)
    for (int k = 0; k < 4; ++k)
      mesh.elements(e, k) = out.tetrahedronlist[e * out.numberofcorners + k] - out.firstnumber;
  orientElementsPositively(mesh);
  return mesh;
}

}  // namespace tetskin
