// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The frame statistics the view's overlay shows (View > Frame statistics):
// frames drawn per second of wall-clock time and the mean draw time since
// the last line, with the run's last step and the last frame's
// deformation and upload. A new line every half second.

#include <chrono>
#include <string>

#include "tetskin/rendering/DeformableSurface.h"

namespace tetskin::gui {

class FrameStatistics {
 public:
  // One frame drawn, in `seconds`.
  void addDraw(double seconds);
  // Whether half a second has passed since the last line.
  bool due() const;
  // "cpu  58.3 fps | step 4.1 ms (120) | deform 0.21 ms | upload 0.05 ms |
  // draw 12.3 ms"; starts counting again.
  std::string line(const char* renderPath, double stepSeconds, long long steps,
                   const FrameTimes& times);

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  int frames_ = 0;
  double drawSeconds_ = 0;
};

}  // namespace tetskin::gui
