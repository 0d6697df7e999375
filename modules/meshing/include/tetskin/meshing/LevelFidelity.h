// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How faithfully a level follows the surface it was made from, and the bound
// build holds every candidate to (doc/user/model-generation.md, "Faithful
// levels"). A level is measured against the object's finest input as read,
// whatever its own input was (a decimation, a wrap, a re-wrap): the one
// surface the user gave and binds.
//
// The bound scales with the level's resolution. A level of element size h
// cannot follow detail finer than h, so it may lie off the input by a part
// of h; a level that lies off by more has lost the shape it had room for (a
// decimation collapsed, a shell torn open, a part dropped). Held to
// input -> level, the direction in which such losses show; level -> input is
// reported only, since it is large by design where a hole was closed.

#include <string>

#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/io/DatasetConfig.h"

namespace tetskin {

// input -> level's mean may be at most this share of h, its max this many h.
inline constexpr double kFidelityMeanShare = 0.5;
inline constexpr double kFidelityMaxShare = 2.0;

// h: the edge of the regular tetrahedron of a given volume (a mesh's mean
// element volume), (6 sqrt(2) V)^(1/3); of a whole mesh, with its total
// volume over its elements (0 for an empty mesh).
double elementSize(double meanElementVolume);
double elementSize(const TetMesh& mesh);

// A level's `boundary` (boundarySurface) measured against `input` both ways
// (oneSidedDistance), with the bounds for the level's `elementSize` and
// whether it lies within them. Both surfaces need at least one triangle.
LevelFidelity measureFidelity(const SurfaceMesh& input, const SurfaceMesh& boundary,
                              double elementSize);

// Why a fidelity is beyond its bounds, e.g. "lies off the input by 5.8% of
// the diagonal on average (at most 1.2% for its element size 2.4%)"; empty
// when within them.
std::string fidelityProblem(const LevelFidelity& fidelity);

}  // namespace tetskin
