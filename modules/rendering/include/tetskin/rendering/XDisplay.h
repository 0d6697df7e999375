// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Whether a window can be opened on the X display. Debian's VTK and Qt's xcb
// platform both abort the process when they cannot connect, so the
// executables ask first and say what to do instead.

#include <string>

namespace tetskin {

// Empty when the display named by DISPLAY accepts a connection; otherwise
// why not ("no DISPLAY is set", "cannot connect to the X display ':99'").
// The first call decides for the whole process (DISPLAY read once).
std::string xDisplayProblem();

}  // namespace tetskin
