// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Candidates.h"

#include <algorithm>
#include <chrono>

#include "tetskin/core/Error.h"
#include "tetskin/meshing/IsolatedJobs.h"
#include "tetskin/meshing/MeshQuality.h"
#include "tetskin/meshing/Meshers.h"

namespace tetskin {
namespace {

TetMesh runMesher(const SurfaceMesh& surface, const CandidateSpec& spec, MesherKind mesher) {
  if (mesher == MesherKind::TetGen)
    return tetrahedralizeWithTetGen(surface, spec.quality, spec.sizeBound);
  return tetrahedralizeWithNetgen(surface, static_cast<NetgenFineness>(spec.quality),
                                  spec.sizeBound);
}

}  // namespace

std::vector<double> distinctQualities(const BuildOptions& options) {
  std::vector<double> qualities = options.qualities;
  std::sort(qualities.begin(), qualities.end());
  qualities.erase(std::unique(qualities.begin(), qualities.end()), qualities.end());
  return qualities;
}

void say(const BuildEvents& events, const std::string& line) {
  if (events.log) events.log(line);
}

double meshCandidates(const std::vector<CandidateSpec>& specs,
                      const std::vector<RepairedInput>& prepared, const BuildOptions& options,
                      const BuildEvents& events, const std::string& stage, Candidates& found) {
  std::vector<MeshJob> jobs;
  for (const CandidateSpec& spec : specs) {
    const SurfaceMesh* surface = &prepared[spec.input].mesh;
    jobs.push_back(
        [surface, spec, mesher = options.mesher] { return runMesher(*surface, spec, mesher); });
  }
  std::size_t done = 0;
  if (events.progress) events.progress(stage, 0, specs.size());
  const auto start = std::chrono::steady_clock::now();
  const std::vector<IsolatedResult> meshed = runIsolated(
      jobs, options.jobs, options.timeoutSeconds,
      [&](std::size_t i, const IsolatedResult& r) {
        ++done;
        if (events.progress) events.progress(stage, done, specs.size());
        if (!r.ok)
          say(events, "candidate " + prepared[specs[i].input].name + " " + specs[i].label +
                          " failed: " + r.error);
      },
      events.cancelled);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  for (std::size_t i = 0; i < specs.size(); ++i) {
    CandidateReport c;
    c.input = prepared[specs[i].input].file;
    c.mesher = toString(options.mesher);
    c.quality = specs[i].quality;
    c.label = specs[i].label;
    c.sizeBound = specs[i].sizeBound;
    c.seconds = meshed[i].seconds;
    c.ok = meshed[i].ok;
    c.error = meshed[i].error;
    TetMesh mesh;
    if (c.ok) {
      mesh = meshed[i].mesh;
      // Nodes that belong to no tetrahedron crash the simulation (report 2.4).
      c.unreferencedNodesRemoved = removeUnreferencedNodes(mesh);
      try {
        validateTetMesh(mesh, prepared[specs[i].input].name + " " + c.label,
                        /*requirePositiveVolume=*/true);
        c.nodes = mesh.nodeCount();
        c.elements = mesh.elementCount();
        c.statistics = measureQuality(mesh);
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
  return seconds;
}

}  // namespace tetskin
