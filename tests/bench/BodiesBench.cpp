// SPDX-License-Identifier: AGPL-3.0-or-later
// Several bodies' cost (issue #71's benchmark): three bundled bunnies at
// their finest level, each with the 64k skin, dropped into a bowl (BOWL.obj
// from data/tools/make_bowl.py, placed 2.5 times larger; see
// bodies_bench.sh) and onto each other. In one run: the steps with every
// contact (the bowl, and the skins against each other) against the same
// steps of the same three bodies with none, from the same state, the two
// stepping by turns (medians over the steps). Prints a table; asserts
// nothing.
//
// usage: bodies_bench BOWL.obj [STEPS] [SETTLE] [SKIN_STIFFNESS]
// (SKIN_STIFFNESS: N/m per skin vertex; default 0, automatic)
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "StepTimes.h"
#include "tetskin/core/Parallel.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/session/SceneRun.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/spatial/ClosedSurfaceDistance.h"

using namespace tetskin;
using bench::StepTimes;

namespace {

using Clock = std::chrono::steady_clock;

void printRow(const char* what, const StepTimes& t) {
  std::printf("  %-34s %7.2f  %7.1f  %8.2f  %6.2f  %8d  %13d\n", what, t.step, 1e3 / t.step,
              t.assembly, t.solve, t.contacts, t.iterations);
}

// How far the skins have gone into each other: the skin vertices that lie
// inside another body's closed skin (its exact signed distance, as the
// obstacles' kernel finds it), and the deepest of them.
struct Interpenetration {
  int vertices = 0;
  double deepest = 0;
};

Interpenetration interpenetration(SimulationSession& session, const std::vector<RunBody>& bodies) {
  const BoundSurface& bound = session.deformedSurface(session.state().positions);
  const SurfaceMesh skin{bound.deformed->positions, bound.surface.triangles, {}, {}};
  std::vector<ClosedSurfaceDistance> skins;
  for (const RunBody& body : bodies) skins.emplace_back(bodyPart(skin, body.range), "a skin");
  std::vector<double> depth(static_cast<std::size_t>(skin.vertexCount()), 0.0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyRange& range = bodies[b].range;
    parallelFor<Index>(range.firstVertex, range.firstVertex + range.vertexCount, 64,
                       [&](const IndexRange<Index>& r) {
                         for (Index v = r.begin(); v != r.end(); ++v) {
                           const Eigen::Vector3d p = skin.positions.row(v).transpose();
                           double& deepest = depth[static_cast<std::size_t>(v)];
                           for (std::size_t other = 0; other < skins.size(); ++other) {
                             if (other == b || !skins[other].bounds().contains(p)) continue;
                             const auto at = skins[other].closest(p);
                             if (at && at->distance < 0) deepest = std::max(deepest, -at->distance);
                           }
                         }
                       });
  }
  Interpenetration result;
  for (double d : depth)
    if (d > 0) {
      ++result.vertices;
      result.deepest = std::max(result.deepest, d);
    }
  return result;
}

void printInterpenetration(const char* when, SimulationSession& session,
                           const std::vector<RunBody>& bodies) {
  const Interpenetration in = interpenetration(session, bodies);
  std::printf("  %s: %d skin vertices inside another body, the deepest %.3f in\n", when,
              in.vertices, in.deepest);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bodies_bench BOWL.obj [STEPS] [SETTLE] [SKIN_STIFFNESS]\n");
    return 2;
  }
  // (Line by line: a run stopped by a timeout keeps what it printed.)
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
  const int settle = argc > 3 ? std::atoi(argv[3]) : 40;
  const double skinStiffness = argc > 4 ? std::atof(argv[4]) : 0.0;
  const std::string data = TETSKIN_SOURCE_DIR "/data/";
  // The bowl's inside reaches down to y = -22.5; each bunny about 10 wide
  // and 9.5 tall, the lowest 1 above the bowl, the others above it and a
  // little aside, so that they land on each other.
  nlohmann::json bodies = nlohmann::json::array();
  const double places[3][3] = {{0, -21.5, 0}, {2.5, -10.5, 0.5}, {-2, 0.5, -0.5}};
  for (const auto& place : places)
    bodies.push_back({{"dataset", data + "bunny.json"},
                      {"surface", data + "bunny_64k.obj"},
                      {"translate", {place[0], place[1], place[2]}}});
  const nlohmann::json json = {
      {"format", "tetskin-scene"},
      {"version", 1},
      {"bodies", bodies},
      // The skins' shell: the mean edge of the 64k skin (0.09) is less than
      // a third of what a vertex travels in a step at the impact's speed
      // (about 17 m/s after the top bunny's fall, 0.29 per step): vertices
      // went through it and the bodies into each other (36,354 contacts at
      // step 140). As thick as that travel.
      {"skin_contact", {{"thickness", 0.3}, {"stiffness", skinStiffness}}},
      {"obstacles", {{{"surface", argv[1]}, {"scale", 2.5}, {"friction", 0.4}}}}};
  const auto loadStart = Clock::now();
  SceneRun run = loadScene(parseScene(json, "bodies_bench", "."));
  const RunSpec spec = resolveRun(run.request, run.dataset.mesh, run.dataset.config);
  std::printf(
      "bodies_bench: 3 bodies, %lld tetrahedra and %lld nodes in all, skins %lld vertices in "
      "all, bowl %lld triangles, %s, %d threads (loaded and bound in %.1f s)\n",
      static_cast<long long>(run.dataset.mesh.elements.rows()),
      static_cast<long long>(run.dataset.mesh.nodes.rows()),
      static_cast<long long>(run.surface->surface.vertexCount()),
      static_cast<long long>(
          run.request.settings.obstacles.front().shape->surface().triangleCount()),
      toString(spec.options.solver), static_cast<int>(tbb::info::default_concurrency()),
      std::chrono::duration<double>(Clock::now() - loadStart).count());

  // With contact: dropped, then `settle` steps into the fall and the first
  // impacts. From the state reached, by turns: the same; the bowl alone (no
  // skin meets another: the skins as one body's); no contact at all.
  SimulationSession contact(run.dataset.mesh, spec);
  contact.bindSurface(run.surface->surface, run.surface->binding, "bodies_bench");
  std::printf("  the skins: a shell %g thick, springs of %g N/m per skin vertex\n",
              contact.simulation().skinThickness(), contact.simulation().skinStiffness());
  // (The drop's course: every tenth step's time, contacts and iterations.)
  for (int i = 0; i < settle; ++i) {
    const StepTimes t = bench::timeStep(contact);
    if ((i + 1) % 10 == 0)
      std::printf("  drop step %3d: %8.2f ms, %5d contacts, %5d cg iterations\n", i + 1, t.step,
                  t.contacts, t.iterations);
    if ((i + 1) % 50 == 0) printInterpenetration("  then", contact, spec.bodies);
  }
  const SimulationState reached = contact.state();
  RunSpec bowlSpec = spec;
  bowlSpec.bodies.clear();
  bowlSpec.options.skinCollisions.selfBodies.clear();
  SimulationSession bowlOnly(run.dataset.mesh, bowlSpec);
  bowlOnly.bindSurface(run.surface->surface, run.surface->binding, "bodies_bench");
  bowlOnly.startFrom({reached.positions, reached.velocities});
  RunSpec freeSpec = bowlSpec;
  freeSpec.options.obstacles.clear();
  SimulationSession free(run.dataset.mesh, freeSpec);
  free.bindSurface(run.surface->surface, run.surface->binding, "bodies_bench");
  free.startFrom({reached.positions, reached.velocities});
  const std::vector<StepTimes> times = bench::stepByTurns({&contact, &bowlOnly, &free}, steps);
  const StepTimes &with = times[0], &bowl = times[1], &without = times[2];
  std::printf(
      "\nafter %d steps of the drop, %d steps by turns (medians)\n"
      "                                      step ms  steps/s  assembly   solve  contacts  "
      "cg iterations\n",
      settle, steps);
  printRow("no contact", without);
  printRow("the bowl only", bowl);
  printRow("the bowl and the skins meeting", with);
  std::printf(
      "  contact's share: %.2f ms per step (%.0f%% of the step with it); the skins meeting: "
      "%.2f ms\n",
      with.step - without.step, 100 * (with.step - without.step) / with.step,
      with.step - bowl.step);
  printInterpenetration("at the end, with contact", contact, spec.bodies);
  printInterpenetration("the bowl only", bowlOnly, spec.bodies);
  return 0;
}
