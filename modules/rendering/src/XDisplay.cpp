// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/XDisplay.h"

#include <X11/Xlib.h>

#include <cstdlib>

namespace tetskin {
namespace {
Display* trialConnection = nullptr;  // open for the process's life (see below)
}  // namespace

std::string xDisplayProblem() {
  static const std::string problem = []() -> std::string {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name) return "no DISPLAY is set";
    // The trial connection stays open for the process's life: an X server
    // started without -noreset (xvfb-run's default) resets when its last
    // client leaves and refuses connections while it does, so closing it
    // here could make the window's own connection, a moment later, fail.
    trialConnection = XOpenDisplay(nullptr);
    if (!trialConnection) return "cannot connect to the X display '" + std::string(name) + "'";
    return {};
  }();
  return problem;
}

}  // namespace tetskin
