// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Surface repair before tetrahedralization (report section 2.3). TetGen aborts
// on open and self-intersecting surfaces, so inputs are cleaned step by step;
// each step is a function of its own and says how much it changed.

#include <string>
#include <utility>
#include <vector>

#include "tetskin/core/SurfaceMesh.h"

namespace tetskin {

// Merges vertices closer than `tolerance` (absolute) into the first of them.
// Returns the number of vertices merged away (left unused; see removeUnusedVertices).
Index weldVertices(SurfaceMesh& mesh, double tolerance);

// Removes triangles with a repeated vertex or an area <= areaTolerance.
Index removeDegenerateTriangles(SurfaceMesh& mesh, double areaTolerance);

// Removes all but the first of triangles that use the same three vertices.
Index removeDuplicateTriangles(SurfaceMesh& mesh);

struct OrientationResult {
  Index flippedTriangles = 0;    // flipped to agree with their neighbours
  Index invertedComponents = 0;  // turned with the outermost one around them
  Index cavities = 0;            // components bounding a cavity (SurfaceNesting.h)
  bool orientable = true;        // false for a Moebius-like surface
};
// Makes neighbouring triangles agree (each shared manifold edge used once in
// each direction; each component keeps the winding most of its triangles
// had), then turns every outermost component outward (positive signed
// volume) with the components inside it. So these keep their winding
// relative to it: the inner sphere of a hollow ball, wound the other way,
// bounds a cavity (SurfaceNesting.h).
OrientationResult orientConsistently(SurfaceMesh& mesh);

// Connected chains of open edges (edges used by exactly one triangle): the rim
// of each hole, or of a dangling strip. Each lists its vertices in walk order.
std::vector<std::vector<int>> boundaryLoops(const SurfaceMesh& mesh);
// Edges used by more than two triangles.
Index nonManifoldEdgeCount(const SurfaceMesh& mesh);

// Closes T-junctions, where one side of a seam is split finer than the
// other (CAD exports, surfaces stitched from patches): a vertex on open edges
// that lies on another open edge, strictly inside it and within `tolerance`
// (absolute) of it, splits that edge's triangle there, keeping its winding.
// Repeats until no such vertex is left. Returns the number of splits.
Index splitTJunctions(SurfaceMesh& mesh, double tolerance);

// Removes flaps, repeatedly: triangles with an open edge that hang off an
// edge of more than two triangles (a scan's stray sheets on a seam). A
// hole's rim inside them then shows as the hole it is (for fillHoles).
// Returns the number removed.
Index removeFlaps(SurfaceMesh& mesh);

// Closes each hole (a chain of open edges, boundaryLoops) whose patch would
// have at most `maxArea`: a fan from the rim's centroid (a new vertex) over
// each open edge, wound as the triangle beside it. The patch may cut
// through the surface near a twisted rim; it is meant for the alpha wrap,
// which takes any soup, so that the wrap encloses the object rather than
// entering a hole wider than its alpha and coating the inside. Returns the
// number of holes closed.
Index fillHoles(SurfaceMesh& mesh, double maxArea);

// Removes triangles with an open edge, repeatedly, until none is left (the
// report's removal of dangling triangles). Returns the number removed.
Index removeOpenTriangles(SurfaceMesh& mesh);

// Pairs of triangles that intersect other than along shared vertices and edges.
// Stops after `limit` pairs.
std::vector<std::pair<int, int>> findSelfIntersections(const SurfaceMesh& mesh,
                                                       std::size_t limit = 1000000);

// The report's repair: for each intersecting pair, all vertices of one
// triangle move to the vertex of the other nearest to their centroid
// (through the triangles sharing them the gap closes). Of the two ways, the
// one whose farthest vertex moves least (ties: `first` onto `second`); a
// pair with a vertex already changed in this call is skipped. Returns the
// number of triangles collapsed.
Index collapseIntersections(SurfaceMesh& mesh, const std::vector<std::pair<int, int>>& pairs);

// Drops vertices no triangle uses and renumbers. Returns how many were dropped.
Index removeUnusedVertices(SurfaceMesh& mesh);

struct RepairOptions {
  double weldTolerance = 1e-7;   // relative to the bounding-box diagonal
  double areaTolerance = 1e-14;  // relative to the squared diagonal
  // How far off an open edge a T-junction's vertex may lie, relative to the
  // diagonal: a float32 export rounds it off by about 1e-7 of the coordinates.
  double tJunctionTolerance = 1e-6;
  int maxIntersectionRounds = 8;
};

// The options' tolerances made absolute for a surface whose bounding-box
// diagonal is `diagonal`: what repairSurface uses, and what `info` uses to
// read a surface as build will.
struct RepairTolerances {
  double weld = 0, area = 0, tJunction = 0;
};
RepairTolerances repairTolerances(const RepairOptions& options, double diagonal);

struct RepairReport {
  Index inputVertices = 0, inputTriangles = 0;
  Index weldedVertices = 0;
  Index degenerateTriangles = 0;
  Index duplicateTriangles = 0;
  Index flippedTriangles = 0;
  Index invertedComponents = 0;
  Index cavities = 0;         // closed components that bound a cavity (left empty by the meshers)
  Index tJunctionsSplit = 0;  // open edges split where a T-junction's vertex lies on them
  Index holes = 0;  // boundary loops left after the splits, before open triangles were removed
  Index openTrianglesRemoved = 0;
  Index intersectingPairs = 0;  // found in the first round
  Index collapsedTriangles = 0;
  int intersectionRounds = 0;
  Index unusedVertices = 0;
  Index outputVertices = 0, outputTriangles = 0;
  // Enclosed volumes, wound outward, before the first collapse and after
  // the repair; both 0 when nothing intersected. The collapse closes small
  // defects such as a scan's folds at a tiny change of volume; parts that
  // overlap (whose shared region the first volume counts twice) come out
  // of it a different shape.
  double volumeBeforeCollapse = 0, volumeAfterCollapse = 0;

  // (name, count) for printing and for the dataset's provenance.
  std::vector<std::pair<std::string, Index>> counts() const;
  // (after - before) / before; 0 when nothing was collapsed.
  double collapseVolumeChange() const;
};

// The relative change of volume above which collapseWarning speaks.
constexpr double kCollapseVolumeTolerance = 0.01;

// Why the repaired shape of `name` should be checked when collapsing its
// self-intersections changed its enclosed volume by more than
// kCollapseVolumeTolerance; empty otherwise.
std::string collapseWarning(const RepairReport& report, const std::string& name);

// Welds duplicate vertices, then removes the degenerate and duplicate
// triangles (welding makes some), adding to the report's counts: the first
// of repairSurface's steps, repeated after each collapse of intersections.
void weldAndClean(SurfaceMesh& mesh, const RepairTolerances& tolerance, RepairReport& report);

// All steps in order: weld, degenerate, duplicates, T-junctions, open
// triangles, self-intersections (collapse and retry), orientation, unused
// vertices.
// Normals and texture coordinates are dropped (meshing needs positions only).
// Throws Error naming `name` when the surface cannot be repaired: nothing is
// left after removing open triangles, or intersections remain after the last
// round.
RepairReport repairSurface(SurfaceMesh& mesh, const std::string& name,
                           const RepairOptions& options = {});

}  // namespace tetskin
