// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The model builder's alpha wrapping (ModelBuilder.cpp): inputs wrapped in
// isolated processes, the wraps checked and measured against their inputs.

#include <memory>
#include <string>
#include <vector>

#include "Candidates.h"

namespace tetskin {

// An input to wrap, as read.
struct WrapRequest {
  std::string name;  // as the user gave it, for messages
  std::string file;  // as the config names it
  SurfaceMesh surface;
  std::string reason;  // why: "--wrap always", or why repair or the meshers refused it
  // A coarser wrap of the same input for a coarser level (rewrappedInputs):
  // its absolute alpha and offset, the surface made ready for it once for
  // all such (wrapReady), and whether the input is an open sheet. Unset:
  // the options' alpha and offset, wrapReady(surface).
  double alpha = 0, offset = 0;
  std::shared_ptr<const SurfaceMesh> ready{};
  bool sheet = false;
};

// Wraps each request in its own process (options.jobs at once, cancellable,
// progress as stage "wrap"), then repairs each wrap (it is closed: repair
// only orients and checks it) and measures it against its input. Says what
// it did; a shell made around an open sheet is a warning naming its
// thickness. A wrap that fails is said and left out, and the first such
// failure goes into `firstFailure` if that is empty.
std::vector<RepairedInput> wrapInputs(std::vector<WrapRequest> requests,
                                      const BuildOptions& options, const BuildEvents& events,
                                      std::string& firstFailure);

// --decimate for a wrapped finest input: coarser inputs wrapped anew from
// the input as read (`finest.original`), each closed and free of
// self-intersections. Alpha grows by kRewrapAlphaFactor from the finest
// wrap's; the offset grows with it. Around an open sheet the offset is
// kSheetOffsetShare of alpha, so the shell's thickness (two offsets) fits
// the resolution of the level meshed from it, and alpha goes up to
// kRewrapLargestSheetAlpha of the diagonal. Around a body the offset is
// kBodyOffsetShare of alpha (never below the finest wrap's) and alpha goes
// up to kRewrapLargestBodyAlpha only: beyond it a wrap bridges the shape's
// concavities, where a decimation of the finest wrap keeps them with as
// few triangles (ModelBuilder.cpp offers both for a body). Wrapped as
// wrapInputs does; each derived, with its wrap measured against the input.
inline constexpr double kRewrapAlphaFactor = 1.5;
inline constexpr double kRewrapLargestSheetAlpha = 0.35;
inline constexpr double kRewrapLargestBodyAlpha = 0.12;
inline constexpr double kBodyOffsetShare = 0.1;
inline constexpr double kSheetOffsetShare = 0.35;
std::vector<RepairedInput> rewrappedInputs(const RepairedInput& finest, const BuildOptions& options,
                                           const BuildEvents& events);

// What of a wrapped `input` its levels are measured against: its triangles
// with a corner within alpha + offset of its finest `wrap` (the outer
// surface: a vertex the wrap hugs lies about the offset from it, one in a
// gap narrower than alpha up to about alpha). The rest is inside the body
// (the overlapping half of a part, an inverted part within another), which
// no level's boundary can follow. `input` itself when nothing is inside.
SurfaceMesh outerSurface(const SurfaceMesh& input, const SurfaceMesh& wrap, const LevelWrap& how);

// How far `surface` (a wrap, or a decimation of one) lies from `input`.
LevelWrap measureWrap(const SurfaceMesh& input, const SurfaceMesh& surface, double alpha,
                      double offset);

}  // namespace tetskin
