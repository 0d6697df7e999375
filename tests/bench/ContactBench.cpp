// SPDX-License-Identifier: AGPL-3.0-or-later
// Contact's cost (issue #70's benchmark): the bundled bunny at its finest
// level with its 64k skin as the contact points, resting in a bowl of about
// 100k triangles (BOWL.obj, from data/tools/make_bowl.py; see
// contact_bench.sh). In one run: the step with skin contact against the
// same step, from the same state, with no obstacle (the two stepping by
// turns, medians over the steps); and the obstacle's
// distance queries alone, TetSkin's exact AABB tree (bounded by the
// contact's search radius, as the step asks, and unbounded) against CGAL's
// AABB tree (its closest point, unbounded), on one thread and on all. Prints a table; asserts
// nothing.
//
// usage: contact_bench BOWL.obj [STEPS] [multigrid]
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "CgalClosest.h"
#include "StepTimes.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/session/SimulationSession.h"

using namespace tetskin;
using bench::StepTimes;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Mean microseconds per point of `query` over `points`, on the threads TBB
// is allowed.
template <class Query>
double microsecondsPerPoint(const Points3& points, const Query& query) {
  const auto start = Clock::now();
  parallelFor<Index>(0, points.rows(), 256, [&](const IndexRange<Index>& range) {
    for (Index i = range.begin(); i != range.end(); ++i) query(points.row(i).transpose());
  });
  return secondsSince(start) * 1e6 / static_cast<double>(points.rows());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: contact_bench BOWL.obj [STEPS] [multigrid]\n");
    return 2;
  }
  const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
  const std::string data = TETSKIN_SOURCE_DIR "/data/";
  // The bunny's finest level with the 64k skin, resting on the bowl's floor.
  const nlohmann::json json = {{"format", "tetskin-scene"},
                               {"version", 1},
                               {"bodies",
                                {{{"dataset", data + "bunny.json"},
                                  {"surface", data + "bunny_64k.obj"},
                                  {"translate", {0, -8.2, 0}},
                                  {"rotate", {0, 30, 0}}}}},
                               {"obstacles", {{{"surface", argv[1]}, {"friction", 0.4}}}}};
  SceneRun run = loadScene(parseScene(json, "contact_bench", "."));
  // (The same solver in both: cg, or multigrid-preconditioned cg.)
  const bool multigrid = argc > 3 && std::string(argv[3]) == "multigrid";
  run.request.settings.solver = multigrid ? SolverKind::Multigrid : SolverKind::ConjugateGradient;
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  const TetMesh level = extractLevel(run.dataset.mesh, run.level);
  const SurfaceMesh& bowl = run.request.settings.obstacles.front().shape->surface();
  std::printf(
      "contact_bench: level %d (%lld tetrahedra, %lld nodes), skin %lld vertices, "
      "obstacle %lld triangles, %d threads, %s\n",
      run.level, static_cast<long long>(level.elementCount()),
      static_cast<long long>(level.nodeCount()),
      static_cast<long long>(run.surface->surface.vertexCount()),
      static_cast<long long>(bowl.triangleCount()),
      static_cast<int>(tbb::info::default_concurrency()), multigrid ? "multigrid" : "cg");

  // The run with contact, settled a while; then the same steps from the
  // same state with no obstacle. The two runs step by turns, so that the
  // machine's drift (other load, clock changes) falls on both alike, and
  // each column is the median over the steps.
  SimulationSession contact(run.dataset.mesh, spec);
  contact.bindSurface(run.surface->surface, run.surface->binding, "bunny.json");
  for (int i = 0; i < 30; ++i) contact.step();
  const SimulationState settled = contact.state();
  RunSpec freeSpec = spec;
  freeSpec.options.obstacles.clear();
  SimulationSession free(run.dataset.mesh, freeSpec);
  free.startFrom({settled.positions, settled.velocities});
  const std::vector<StepTimes> times = bench::stepByTurns({&contact, &free}, steps);
  const StepTimes& with = times[0];
  const StepTimes& without = times[1];

  std::printf(
      "\nsteps (ms per step, median of %d, by turns)   step   assembly   solve   contacts   "
      "cg iterations\n",
      steps);
  std::printf("  without obstacles                        %7.2f  %8.2f  %6.2f  %9d  %14d\n",
              without.step, without.assembly, without.solve, without.contacts, without.iterations);
  std::printf("  skin contact with the bowl               %7.2f  %8.2f  %6.2f  %9d  %14d\n",
              with.step, with.assembly, with.solve, with.contacts, with.iterations);
  std::printf("  contact's share: %.2f ms per step (%.0f%% of the step with it)\n",
              with.step - without.step, 100 * (with.step - without.step) / with.step);

  // The distance queries alone, at the settled skin.
  const Points3 skin = contact.deformedSurface(settled.positions).deformed->positions;
  const Obstacle& obstacle = run.request.settings.obstacles.front();
  const double radius = 0.05 * boundingBox(level.nodes).diagonal();  // (the contact's)
  const auto buildStart = Clock::now();
  const bench::CgalTriangleTree cgal(bowl);
  const double cgalBuild = secondsSince(buildStart);
  Index near = 0;
  double disagreement = 0;
  for (Index v = 0; v < skin.rows(); ++v) {
    const Eigen::Vector3d p = skin.row(v).transpose();
    if (const auto hit = closestPointOf(obstacle, 0, p, radius)) {
      ++near;
      const Eigen::Vector3d local = obstacle.placement.toLocal(p);
      const double exact = (cgal.closest(local).first - local).norm() * obstacle.placement.scale;
      disagreement = std::max(disagreement, std::abs(std::abs(hit->distance) - exact));
    }
  }
  std::printf(
      "\ndistance queries at the settled skin (us per skin vertex; %lld of %lld within "
      "the search radius %.3g)\n",
      static_cast<long long>(near), static_cast<long long>(skin.rows()), radius);
  std::printf(
      "  threads   TetSkin bounded   TetSkin unbounded   CGAL (closest point, unbounded)\n");
  const int cores = static_cast<int>(tbb::info::default_concurrency());
  std::vector<int> threadCounts;  // 1, 2, 4, ... and all
  for (int threads = 1; threads < cores; threads *= 2) threadCounts.push_back(threads);
  threadCounts.push_back(cores);
  for (const int threads : threadCounts) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(threads));
    const double ours = microsecondsPerPoint(
        skin, [&](const Eigen::Vector3d& p) { (void)closestPointOf(obstacle, 0, p, radius); });
    const double unbounded = microsecondsPerPoint(skin, [&](const Eigen::Vector3d& p) {
      (void)closestPointOf(obstacle, 0, p, std::numeric_limits<double>::infinity());
    });
    const double theirs = microsecondsPerPoint(
        skin, [&](const Eigen::Vector3d& p) { (void)cgal.closest(obstacle.placement.toLocal(p)); });
    std::printf("  %7d   %15.3f   %17.3f   %31.3f\n", threads, ours, unbounded, theirs);
  }
  std::printf("  CGAL's tree built in %.1f ms; the distances agree to %.2g (model units)\n",
              cgalBuild * 1e3, disagreement);
  return 0;
}
