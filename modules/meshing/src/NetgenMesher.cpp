// SPDX-License-Identifier: AGPL-3.0-or-later
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/meshing/Meshers.h"

#ifdef TETSKIN_HAVE_NETGEN
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "NetgenModuleApi.h"
#endif

namespace tetskin {

const char* netgenFinenessName(NetgenFineness fineness) {
  static const char* names[] = {"very coarse", "coarse", "moderate", "fine", "very fine"};
  return names[static_cast<int>(fineness)];
}

#ifdef TETSKIN_HAVE_NETGEN

namespace {

// The Netgen module's functions, loaded once (NetgenModuleApi.h says why
// it is a module of its own).
struct NetgenModule {
  decltype(&tetskin_netgen_mesh) mesh = nullptr;
  decltype(&tetskin_netgen_free) free = nullptr;
};

// The file of the code running this: the executable, or the library (the
// Python module) that holds it.
std::filesystem::path runningObject() {
  Dl_info info{};
  std::error_code error;
  if (dladdr(reinterpret_cast<void*>(&runningObject), &info) && info.dli_fname &&
      info.dli_fname[0] == '/')  // (the executable's own name may be relative)
    if (auto path = std::filesystem::canonical(info.dli_fname, error); !error) return path;
  return std::filesystem::canonical("/proc/self/exe", error);
}

// Where the module is: TETSKIN_NETGEN_MODULE if set; beside the build's
// targets for what runs from the build folder; else installed, at
// lib/tetskin/ under the prefix the running file is installed in (bin/tetskin,
// or the Python package's folder: the first folder above it that has it).
std::filesystem::path netgenModulePath() {
  if (const char* given = std::getenv("TETSKIN_NETGEN_MODULE"); given && *given) return given;
  const std::filesystem::path object = runningObject();
  const std::filesystem::path built = TETSKIN_NETGEN_MODULE_BUILT;
  const std::string buildDir = TETSKIN_BUILD_DIR;
  if (object.string().rfind(buildDir + "/", 0) == 0) return built;
  for (std::filesystem::path folder = object.parent_path(); folder.has_relative_path();
       folder = folder.parent_path())
    if (std::filesystem::exists(folder / TETSKIN_NETGEN_MODULE_INSTALLED))
      return folder / TETSKIN_NETGEN_MODULE_INSTALLED;
  return built;
}

const NetgenModule& netgenModule() {
  static NetgenModule module;
  static std::string error;
  static std::once_flag loaded;
  std::call_once(loaded, [] {
    const std::filesystem::path path = netgenModulePath();
    // (Kept loaded: nglib's static state lives as long as the process.)
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      error = "cannot load the Netgen module " + path.string() + ": " + (why ? why : "?") +
              " (TETSKIN_NETGEN_MODULE gives its path)";
      return;
    }
    module.mesh = reinterpret_cast<decltype(module.mesh)>(dlsym(handle, TETSKIN_NETGEN_MESH));
    module.free = reinterpret_cast<decltype(module.free)>(dlsym(handle, TETSKIN_NETGEN_FREE));
    if (!module.mesh || !module.free)
      error = "the Netgen module " + path.string() + " lacks " + TETSKIN_NETGEN_MESH;
  });
  if (!error.empty()) throw Error(error);
  return module;
}

}  // namespace

bool netgenAvailable() {
  return true;
}

void loadNetgen() {
  netgenModule();
}

TetMesh tetrahedralizeWithNetgen(const SurfaceMesh& surface, NetgenFineness fineness,
                                 double maxEdge) {
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
  const TetskinNetgenParameters parameters{
      maxEdge > 0.0 ? maxEdge : preset.maxhFraction * boundingBox(surface).diagonal(),
      preset.fineness, preset.grading, preset.segments, preset.curvature};
  std::vector<double> corners(9 * static_cast<std::size_t>(surface.triangleCount()));
  for (Index t = 0; t < surface.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        corners[static_cast<std::size_t>(9 * t + 3 * k + c)] =
            surface.positions(surface.triangles(t, k), c);
  const NetgenModule& netgen = netgenModule();
  TetskinNetgenMesh result{};
  netgen.mesh(corners.data(), corners.size() / 9, &parameters, &result);
  struct Free {
    const NetgenModule& netgen;
    TetskinNetgenMesh& result;
    ~Free() { netgen.free(&result); }
  } freeGuard{netgen, result};
  if (result.error) throw Error(result.error);
  TetMesh out;
  out.nodes = Eigen::Map<const Points3>(result.nodes, result.nodeCount, 3);
  out.elements = Eigen::Map<const Tetrahedra>(result.elements, result.elementCount, 4);
  orientElementsPositively(out);
  return out;
}

#else

bool netgenAvailable() {
  return false;
}

void loadNetgen() {}

TetMesh tetrahedralizeWithNetgen(const SurfaceMesh&, NetgenFineness, double) {
  throw Error("this TetSkin was built without Netgen (TETSKIN_WITH_NETGEN=OFF)");
}

#endif

}  // namespace tetskin
