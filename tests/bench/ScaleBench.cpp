// SPDX-License-Identifier: AGPL-3.0-or-later
// Binding and deformation at scale (issue #56): bunny_64k Loop-subdivided
// SUBDIVISIONS times (default 5: 32.8M vertices, 65.5M triangles), bound
// to the bundled dataset's finest level and deformed frame by frame, with
// the time and the peak memory of each stage. The frame is set beside a
// memcpy of the bytes it touches, at the copy rate measured in the same run
// on a 1 GiB buffer (copying the frame's own bytes would take two buffers
// of that size); the binding beside CGAL's closest-point query on the same
// surface (binding_bench's baseline). Prints a table; asserts nothing.
// Usage: scale_bench [SUBDIVISIONS] [FRAMES (default 5)]
#include <sys/resource.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "CgalClosest.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/VtkConversion.h"

using namespace tetskin;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The process's peak resident memory so far, in GB.
double peakGb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1e6;  // (KiB, read as kB: GB)
}

void row(const char* stage, double seconds, const std::string& note) {
  std::printf("%-34s %10.3f %10.2f  %s\n", stage, seconds, peakGb(), note.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const int subdivisions = argc > 1 ? std::atoi(argv[1]) : 5;
  const int frames = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const std::string data = std::string(TETSKIN_SOURCE_DIR) + "/data/";
  const Dataset d = loadDataset(data + "bunny.json");
  const int level = d.mesh.finestLevel();
  std::printf("bunny_64k, Loop x%d, bound to level %d (%lld tetrahedra), %u cores\n", subdivisions,
              level,
              static_cast<long long>(d.mesh.levels[static_cast<std::size_t>(level)].elementCount),
              std::thread::hardware_concurrency());
  std::printf("%-34s %10s %10s\n", "stage", "seconds", "peak GB");

  auto start = Clock::now();
  SurfaceMesh surface;
  {
    auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
    loop->SetInputData(toVtkPolyData(readObj(data + "bunny_64k.obj")));
    loop->SetNumberOfSubdivisions(subdivisions);
    loop->Update();
    surface = fromVtkPolyData(loop->GetOutput(), "subdivided");
  }
  row("subdivide (VTK, 1 thread)", since(start),
      std::to_string(surface.vertexCount()) + " vertices, " +
          std::to_string(surface.triangleCount()) + " triangles");

  start = Clock::now();
  const SurfaceBinding binding = bindSurface(surface, d.mesh, level);
  const double bindSeconds = since(start);
  row("bind (closest, all cores)", bindSeconds,
      std::to_string(1e9 * bindSeconds / static_cast<double>(surface.vertexCount())).substr(0, 5) +
          " ns a vertex");
  {
    start = Clock::now();
    const SurfaceBinding cgal = bench::bindWithCgal(surface, d.mesh, level);
    const double cgalSeconds = since(start);
    Index same = 0;
    for (Index v = 0; v < surface.vertexCount(); ++v)
      same += (binding.controlIds.row(v).head<3>() == cgal.controlIds.row(v).head<3>()) ? 1 : 0;
    row("CGAL AABB_tree closest point (all)", cgalSeconds,
        std::to_string(cgalSeconds / bindSeconds).substr(0, 4) + "x closest's time; " +
            std::to_string(100.0 * static_cast<double>(same) /
                           static_cast<double>(surface.vertexCount()))
                .substr(0, 5) +
            "% the same triangle");
  }

  start = Clock::now();
  SurfaceDeformer deformer(surface, binding, d.mesh.nodes);
  row("deformer (binding packed)", since(start), "");
  const Points3 control = d.mesh.nodes * 1.01;
  Points3 positions, normals;
  start = Clock::now();
  deformer.deform(control, positions, normals);
  row("first frame (outputs allocated)", since(start), "");
  double best = 1e30;
  for (int f = 0; f < frames; ++f) {
    start = Clock::now();
    deformer.deform(control, positions, normals);
    best = std::min(best, since(start));
  }
  const double bytes = static_cast<double>(deformer.bytesPerFrame());
  row("frame (positions + normals), best", best,
      std::to_string(static_cast<long long>(bytes / 1e6)) + " MB touched");

  // The copy rate, on 1 GiB (well beyond the caches), the best of 5.
  const std::size_t copyBytes = std::size_t(1) << 30;
  std::vector<char> from(copyBytes, 1), to(copyBytes, 0);
  double copy = 1e30;
  for (int i = 0; i < 5; ++i) {
    start = Clock::now();
    std::memcpy(to.data(), from.data(), copyBytes);
    copy = std::min(copy, since(start));
  }
  const double copyFrame = copy * bytes / static_cast<double>(copyBytes);
  row("memcpy of the frame's bytes", copyFrame,
      std::to_string(static_cast<double>(copyBytes) / copy / 1e9).substr(0, 5) +
          " GB/s on 1 GiB; the frame takes " + std::to_string(best / copyFrame).substr(0, 4) + "x");
  std::printf("(%s)\n", to[copyBytes / 2] == 1 ? "copied" : "?");
  return 0;
}
