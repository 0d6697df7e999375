// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The model builder's alpha wrapping (ModelBuilder.cpp): inputs wrapped in
// isolated processes, the wraps checked and measured against their inputs.

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

// How far `surface` (a wrap, or a decimation of one) lies from `input`.
LevelWrap measureWrap(const SurfaceMesh& input, const SurfaceMesh& surface, double alpha,
                      double offset);

}  // namespace tetskin
