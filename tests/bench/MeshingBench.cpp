// SPDX-License-Identifier: AGPL-3.0-or-later
// Model generation on the bundled bunny, stage by stage, with the meshing
// stage run on 1 job and on all cores in the same run (the baseline is the
// 1-job run). Prints a table; asserts nothing.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/LevelSelection.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/vtkio/SurfaceFile.h"

using namespace tetskin;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

int main(int argc, char** argv) {
  const std::string input = std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj";
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("tetskin build %s --decimate --levels 3 --min-elements 600 --max-elements 12000\n",
              input.c_str());
  std::printf("%-24s %12s\n", "stage", "seconds");
  for (int jobs : {1, cores}) {
    auto t = Clock::now();
    SurfaceMesh mesh = readObj(input);
    const double readSeconds = since(t);
    BuildOptions options;
    options.decimate = true;
    options.jobs = jobs;
    const BuildResult r = buildDataset({{"bunny.obj", std::move(mesh), ""}}, options);
    Dataset dataset = r.dataset;
    const auto out = std::filesystem::temp_directory_path() / "tetskin-meshing-bench.json";
    t = Clock::now();
    saveDataset(out, dataset);
    const double writeSeconds = since(t);
    std::printf("-- %d job(s), %zu candidates\n", jobs, r.candidates.size());
    std::printf("%-24s %12.3f\n", "read OBJ", readSeconds);
    double total = readSeconds + writeSeconds;
    for (const auto& [stage, seconds] : r.stageSeconds) {
      std::printf("%-24s %12.3f\n", stage.c_str(), seconds);
      total += seconds;
    }
    std::printf("%-24s %12.3f\n", "write dataset", writeSeconds);
    std::printf("%-24s %12.3f\n", "total", total);
    for (const char* ext : {".json", ".node", ".ele"})
      std::filesystem::remove(std::filesystem::path(out).replace_extension(ext));
  }
  // The level targets driving the work on a fine scan: bunny_64k (or a
  // scan given as the first argument) with the demo's targets, on all
  // cores: wall time, candidates meshed and skipped, each level against its
  // target.
  const std::string scan =
      argc > 1 ? std::string(argv[1]) : std::string(TETSKIN_SOURCE_DIR) + "/data/bunny_64k.obj";
  SurfaceMesh fine = readSurface(scan);
  std::printf(
      "\ntetskin build %s --decimate --levels 3 --min-elements 600 --max-elements 12000 "
      "(%lld triangles, %d jobs)\n",
      scan.c_str(), static_cast<long long>(fine.triangleCount()), cores);
  BuildOptions options;
  options.decimate = true;
  options.jobs = cores;
  const auto t = Clock::now();
  const BuildResult r = buildDataset({{scan, std::move(fine), ""}}, options);
  const double seconds = since(t);
  std::printf("%-24s %12.3f\n", "total", seconds);
  std::printf("candidates: %zu meshed, %zu skipped\n", r.candidates.size(), r.skippedCandidates);
  const std::vector<double> targets =
      levelTargets(options.minElements, options.maxElements, options.levels);
  for (std::size_t k = 0; k < r.chosen.size(); ++k) {
    const double count = static_cast<double>(r.dataset.mesh.levels[k].elementCount);
    std::printf("level %zu: %8.0f elements, target %8.0f (%+.1f%%)\n", k, count, targets[k],
                100 * (count / targets[k] - 1));
  }
  return 0;
}
