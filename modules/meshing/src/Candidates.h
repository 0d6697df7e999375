// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The model builder's candidates (ModelBuilder.cpp): the repaired inputs,
// what to mesh, and the meshes made, cleaned and measured, in search order.
// Shared by the quality round and the sizing rounds (SizedCandidates.cpp).

#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/meshing/ModelBuilder.h"
#include "tetskin/meshing/SurfaceRepair.h"

namespace tetskin {

struct RepairedInput {
  std::string name;
  std::string file;
  SurfaceMesh mesh;
  RepairReport repair;
  bool derived = false;  // made by decimation
  // Made by alpha wrapping the input `file` (or decimated from such a wrap):
  // how, and how far from the input it lies.
  std::optional<LevelWrap> wrap;
  std::string wrapReason;  // why the input was wrapped
  SurfaceMesh original;    // the input as read, when wrapped: what `wrap` measures against
};

struct CandidateSpec {
  std::size_t input;
  double quality;  // TetGen radius-edge bound, or Netgen preset index
  std::string label;
  double sizeBound = 0;  // TetGen volume bound (-a) or Netgen edge bound (maxh); 0: none
};

// The candidates found so far: per candidate its report, its mesh and its
// element count (-1 when it failed), all in search order.
struct Candidates {
  std::vector<CandidateReport> reports;
  std::vector<TetMesh> meshes;
  std::vector<Index> counts;
  std::size_t skipped = 0;  // left unmeshed: predictably above the largest target
};

// Whether a candidate was meshed, is well shaped and lies within its
// fidelity bound (LevelFidelity.h): what the level selection takes.
bool faithful(const CandidateReport& candidate);

// The TetGen qualities asked for, each once, best (closest to 1) first: the
// order of the quality candidates and of the sizing's first round.
std::vector<double> distinctQualities(const BuildOptions& options);

// The builder's log line, when the caller listens.
void say(const BuildEvents& events, const std::string& line);

// Meshes every spec in its own process, then cleans and measures each mesh
// (unreferenced nodes removed, elements validated, quality) and appends it
// to `found` in spec order. `stage` names the progress. Returns the wall
// time of the meshing.
//
// With `pruneAbove` > 0, the specs without a size bound are meshed coarse
// to fine (inputs with fewer triangles first, each from its loosest quality
// bound to its finest), and a spec is skipped (counted in found.skipped, not
// appended) once a candidate of an input with no more triangles, at a bound
// no finer, came out above `pruneAbove` elements: finer bounds and finer
// inputs give more elements, so it would lie farther still from every target
// at or below `pruneAbove`.
//
// Each candidate meshed is measured against `reference` (the object's
// finest input as read: measureFidelity, LevelFidelity.h) into its report's
// `fidelity`; one with flat elements (flatElementProblem, MeshQuality.h) or
// a pinched boundary (an edge of more than two faces) is rejected as a
// failed run is.
double meshCandidates(const std::vector<CandidateSpec>& specs,
                      const std::vector<RepairedInput>& prepared, const SurfaceMesh& reference,
                      const BuildOptions& options, const BuildEvents& events,
                      const std::string& stage, Candidates& found, double pruneAbove = 0);

// `build --size-to-targets`: for each level target that no candidate meets
// within kSizingTolerance (TargetSizing.h), rounds of candidates under an
// element size bound aimed at it, appended to `found` after the quality
// candidates, so that on equal distance those still win. Returns the wall
// time of the meshing.
double addSizedCandidates(const std::vector<RepairedInput>& prepared, const SurfaceMesh& reference,
                          const std::vector<double>& targets, const BuildOptions& options,
                          const BuildEvents& events, Candidates& found);

}  // namespace tetskin
