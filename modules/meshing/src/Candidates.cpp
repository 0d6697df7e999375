// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Candidates.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/core/Error.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/meshing/LevelFidelity.h"
#include "tetskin/meshing/MeshQuality.h"
#include "tetskin/meshing/Meshers.h"
#include "tetskin/meshing/SurfaceRepair.h"

namespace tetskin {
namespace {

TetMesh runMesher(const SurfaceMesh& surface, const CandidateSpec& spec, MesherKind mesher) {
  if (mesher == MesherKind::TetGen)
    return tetrahedralizeWithTetGen(surface, spec.quality, spec.sizeBound);
  return tetrahedralizeWithNetgen(surface, static_cast<NetgenFineness>(spec.quality),
                                  spec.sizeBound);
}

// How loose a spec's quality bound is: TetGen's radius-edge ratio (larger is
// looser), Netgen's preset (lower is coarser).
double looseness(const CandidateSpec& spec, MesherKind mesher) {
  return mesher == MesherKind::TetGen ? spec.quality : -spec.quality;
}

}  // namespace

std::vector<double> distinctQualities(const BuildOptions& options) {
  std::vector<double> qualities = options.qualities;
  std::sort(qualities.begin(), qualities.end());
  qualities.erase(std::unique(qualities.begin(), qualities.end()), qualities.end());
  return qualities;
}

bool faithful(const CandidateReport& candidate) {
  return candidate.ok && (!candidate.fidelity || candidate.fidelity->faithful);
}

void say(const BuildEvents& events, const std::string& line) {
  if (events.log) events.log(line);
}

double meshCandidates(const std::vector<CandidateSpec>& specs,
                      const std::vector<RepairedInput>& prepared, const SurfaceMesh& reference,
                      const BuildOptions& options, const BuildEvents& events,
                      const std::string& stage, Candidates& found, double pruneAbove) {
  auto triangles = [&](std::size_t spec) {
    return prepared[specs[spec].input].mesh.triangleCount();
  };
  // The order the specs run in (and the jobs' order): coarse to fine when
  // pruning, as given otherwise.
  std::vector<std::size_t> order(specs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (pruneAbove > 0)
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (triangles(a) != triangles(b)) return triangles(a) < triangles(b);
      return looseness(specs[a], options.mesher) > looseness(specs[b], options.mesher);
    });
  std::vector<MeshJob> jobs;
  for (std::size_t i : order) {
    const SurfaceMesh* surface = &prepared[specs[i].input].mesh;
    jobs.push_back([surface, spec = specs[i], mesher = options.mesher] {
      return runMesher(*surface, spec, mesher);
    });
  }
  std::vector<std::size_t> position(specs.size());  // of each spec in `order`
  for (std::size_t job = 0; job < order.size(); ++job) position[order[job]] = job;
  // Whether spec j's count bounds spec i's from below: j runs first, both
  // without a size bound, at a bound no finer, on an input with no more
  // triangles (Netgen remeshes the surface, so for it only the same input).
  auto bounds = [&](std::size_t j, std::size_t i) {
    return position[j] < position[i] && specs[j].sizeBound == 0 && specs[i].sizeBound == 0 &&
           (options.mesher == MesherKind::TetGen ? triangles(j) <= triangles(i)
                                                 : specs[j].input == specs[i].input) &&
           looseness(specs[j], options.mesher) >= looseness(specs[i], options.mesher);
  };
  // The element counts of the specs meshed so far (by spec; -1: not yet,
  // or failed or flat: a candidate rejected bounds nothing, else an input
  // whose coarse candidates are all flat would keep none).
  std::vector<Index> meshedCount(specs.size(), -1);
  // Each meshed spec's quality, measured as its job ends (by spec).
  std::vector<std::optional<TetQuality>> quality(specs.size());
  // The spec above the largest target that bounds spec i, if any.
  auto overTarget = [&](std::size_t i) -> std::optional<std::size_t> {
    if (!(pruneAbove > 0)) return std::nullopt;
    for (std::size_t j = 0; j < specs.size(); ++j)
      if (static_cast<double>(meshedCount[j]) > pruneAbove && bounds(j, i)) return j;
    return std::nullopt;
  };
  SkipJob skip;
  if (pruneAbove > 0)
    skip = [&](std::size_t job) -> std::string {
      const std::optional<std::size_t> j = overTarget(order[job]);
      return j ? "above the largest target, as " + prepared[specs[*j].input].name + " " +
                     specs[*j].label + " (" + std::to_string(meshedCount[*j]) + " elements)"
               : std::string();
    };
  if (options.mesher == MesherKind::Netgen) loadNetgen();  // once, before the jobs fork
  std::size_t done = 0;
  if (events.progress) events.progress(stage, 0, specs.size());
  const auto start = std::chrono::steady_clock::now();
  std::vector<IsolatedResult> meshed = runIsolated(
      jobs, options.jobs, options.timeoutSeconds,
      [&](std::size_t job, const IsolatedResult& r) {
        const std::size_t i = order[job];
        ++done;
        if (events.progress) events.progress(stage, done, specs.size());
        if (r.ok) try {
            // (Validated first: a mesh with a bad index is measured nowhere.)
            validateTetMesh(r.mesh, "", /*requirePositiveVolume=*/true);
            quality[i] = measureQuality(r.mesh);
            if (flatElementProblem(*quality[i]).empty()) meshedCount[i] = r.mesh.elementCount();
          } catch (const Error&) {
            // (Said with its name when the candidate is reported below.)
          }
        if (!r.ok)
          say(events, "candidate " + prepared[specs[i].input].name + " " + specs[i].label +
                          " failed: " + r.error);
      },
      events.cancelled, skip);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Back in spec order: the selection's search order.
  std::vector<IsolatedResult> bySpec(specs.size());
  for (std::size_t job = 0; job < order.size(); ++job) bySpec[order[job]] = std::move(meshed[job]);

  // Which jobs were skipped depends on which others had ended when each
  // started; the same rule over every count leaves out the same candidates
  // whatever the timing (those meshed before a bounding one ended too), so
  // a build's candidates and levels do not depend on --jobs or the load.
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (bySpec[i].skipped || overTarget(i)) {
      ++skipped;
      continue;
    }
    CandidateReport c;
    c.input = prepared[specs[i].input].file;
    c.mesher = toString(options.mesher);
    c.quality = specs[i].quality;
    c.label = specs[i].label;
    c.sizeBound = specs[i].sizeBound;
    c.wrap = prepared[specs[i].input].wrap;
    c.seconds = bySpec[i].seconds;
    c.ok = bySpec[i].ok;
    c.error = bySpec[i].error;
    TetMesh mesh;
    if (c.ok) {
      mesh = std::move(bySpec[i].mesh);
      // Nodes that belong to no tetrahedron crash the simulation (report 2.4).
      c.unreferencedNodesRemoved = removeUnreferencedNodes(mesh);
      try {
        validateTetMesh(mesh, prepared[specs[i].input].name + " " + c.label,
                        /*requirePositiveVolume=*/true);
        c.nodes = mesh.nodeCount();
        c.elements = mesh.elementCount();
        // (Measured as its job ended: the nodes removed belong to no element.)
        c.statistics = *quality[i];
        if (const std::string flat = flatElementProblem(c.statistics); !flat.empty())
          throw Error(prepared[specs[i].input].name + " " + c.label + " " + flat);
        // A level's boundary carries the bound surface and the contacts: a
        // pinched edge (two parts of the body touching along it, as a
        // collapsed decimation leaves) makes it no closed manifold.
        const SurfaceMesh boundary = boundarySurface(mesh);
        if (const Index pinched = nonManifoldEdgeCount(boundary); pinched > 0)
          throw Error(prepared[specs[i].input].name + " " + c.label + ": its boundary has " +
                      std::to_string(pinched) +
                      " edge(s) of more than two faces (parts touching along an edge)");
        c.fidelity = measureFidelity(
            reference, boundary,
            elementSize(c.statistics.totalVolume / static_cast<double>(c.elements)));
      } catch (const Error& e) {
        c.ok = false;
        c.error = e.what();
        mesh = TetMesh{};
        say(events, "candidate rejected: " + c.error);
      }
    }
    found.counts.push_back(c.ok ? c.elements : -1);
    found.reports.push_back(std::move(c));
    found.meshes.push_back(std::move(mesh));
  }
  if (skipped > 0)
    say(events, "skipped " + std::to_string(skipped) + " of " + std::to_string(specs.size()) +
                    " candidates: finer than one already above the largest target (" +
                    std::to_string(static_cast<Index>(pruneAbove)) + " elements)");
  found.skipped += skipped;
  return seconds;
}

}  // namespace tetskin
