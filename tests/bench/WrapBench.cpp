// SPDX-License-Identifier: AGPL-3.0-or-later
// build --wrap's cost: the alpha wrap's time (wrapReady and the wrap, as
// build runs them) and size against the input's size and alpha, next to TetGen meshing the same
// surface in the same run (the input itself where it is closed, else the wrap), so the wrap's time
// reads against the meshing build does anyway. Prints a table; asserts
// nothing.
//
//   wrap_bench [--quick]   (--quick: the default alpha only)
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/AlphaWrap.h"
#include "tetskin/meshing/Meshers.h"
#include "tetskin/meshing/SurfaceRepair.h"

using namespace tetskin;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Each triangle split in four at its edges' midpoints (shared midpoints
// shared): 4x the triangles, the same shape; a 256k-triangle scan's stand-in.
SurfaceMesh splitInFour(const SurfaceMesh& in) {
  SurfaceMesh out;
  std::vector<Eigen::RowVector3d> points;
  for (Index v = 0; v < in.vertexCount(); ++v) points.push_back(in.positions.row(v));
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    const auto [it, added] = midpoint.emplace(key, static_cast<int>(points.size()));
    if (added) points.push_back(0.5 * (in.positions.row(a) + in.positions.row(b)));
    return it->second;
  };
  std::vector<std::array<int, 3>> triangles;
  for (Index t = 0; t < in.triangleCount(); ++t) {
    const int a = in.triangles(t, 0), b = in.triangles(t, 1), c = in.triangles(t, 2);
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    triangles.insert(triangles.end(), {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
  }
  out.positions.resize(static_cast<Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    out.positions.row(static_cast<Index>(i)) = points[i];
  out.triangles.resize(static_cast<Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) out.triangles(static_cast<Index>(t), k) = triangles[t][k];
  return out;
}

// The bunny cut open as tests/data/bunny_holed.obj is: its base and one
// ear's tip removed.
SurfaceMesh cutOpen(const SurfaceMesh& in) {
  const double low = in.positions.col(1).minCoeff(), high = in.positions.col(1).maxCoeff();
  const double base = low + 0.06 * (high - low), tip = high - 0.05 * (high - low);
  SurfaceMesh out;
  out.positions = in.positions;
  std::vector<Index> kept;
  for (Index t = 0; t < in.triangleCount(); ++t) {
    bool allLow = true, allHigh = true;
    for (int k = 0; k < 3; ++k) {
      const double y = in.positions(in.triangles(t, k), 1);
      allLow = allLow && y < base;
      allHigh = allHigh && y > tip;
    }
    if (!allLow && !allHigh) kept.push_back(t);
  }
  out.triangles.resize(static_cast<Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
    out.triangles.row(static_cast<Index>(i)) = in.triangles.row(kept[i]);
  return out;
}

// TetGen at the loosest quality (q2, as build's first candidate) on a
// closed surface; -1 when it refuses it.
double tetgenSeconds(const SurfaceMesh& closed, Index& elements) {
  const auto t = Clock::now();
  try {
    elements = tetrahedralizeWithTetGen(closed, 2.0).elementCount();
  } catch (...) {
    elements = -1;
    return -1;
  }
  return since(t);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const SurfaceMesh bunny64k = readObj(data + "bunny_64k.obj");
  struct Input {
    std::string name;
    SurfaceMesh mesh;
    bool closed;
  };
  std::vector<Input> inputs = {
      {"bunny.obj", readObj(data + "bunny.obj"), true},
      {"bunny_8k.obj", readObj(data + "bunny_8k.obj"), true},
      {"bunny_64k.obj", bunny64k, true},
      {"bunny_64k cut open", cutOpen(bunny64k), false},
      {"bunny_64k cut open, split 4x", splitInFour(cutOpen(bunny64k)), false}};
  const WrapOptions defaults;
  std::vector<double> alphas = {defaults.alpha};
  if (!quick) alphas = {1.0 / 20, defaults.alpha, 1.0 / 100};
  std::printf(
      "alpha wrap (CGAL 3D Alpha Wrapping), offset %g of the diagonal, 1 thread; TetGen "
      "-pq2 in the same run\n",
      defaults.offset);
  std::printf("%-30s %9s %7s %9s %9s %12s %10s %10s\n", "input", "triangles", "alpha", "wrap s",
              "wrap tris", "TetGen input", "TetGen wrap", "wrap tets");
  for (const Input& input : inputs) {
    const double diagonal = boundingBox(input.mesh).diagonal();
    Index inputElements = 0;
    const double meshInput = input.closed ? tetgenSeconds(input.mesh, inputElements) : -1;
    for (double alpha : alphas) {
      const auto t = Clock::now();
      const SurfaceMesh wrap = alphaWrap(wrapReady(input.mesh), alpha * diagonal,
                                         defaults.offset * diagonal, input.name);
      const double wrapSeconds = since(t);
      Index wrapElements = 0;
      const double meshWrap = tetgenSeconds(wrap, wrapElements);
      char inputCell[32] = "open";
      if (input.closed) std::snprintf(inputCell, sizeof inputCell, "%.2f s", meshInput);
      std::printf("%-30s %9lld %7s %9.2f %9lld %12s %8.2f s %10lld\n", input.name.c_str(),
                  static_cast<long long>(input.mesh.triangleCount()),
                  ("1/" + std::to_string(static_cast<int>(1 / alpha + 0.5))).c_str(), wrapSeconds,
                  static_cast<long long>(wrap.triangleCount()), inputCell, meshWrap,
                  static_cast<long long>(wrapElements));
      std::fflush(stdout);
    }
  }
  return 0;
}
