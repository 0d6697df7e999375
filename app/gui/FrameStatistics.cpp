// SPDX-License-Identifier: AGPL-3.0-or-later
#include "FrameStatistics.h"

#include <algorithm>
#include <cstdio>

namespace tetskin::gui {

void FrameStatistics::addDraw(double seconds) {
  drawSeconds_ += seconds;
  ++frames_;
}

bool FrameStatistics::due() const {
  return std::chrono::steady_clock::now() - start_ > std::chrono::milliseconds(500);
}

std::string FrameStatistics::line(const char* renderPath, double stepSeconds, long long steps,
                                  const FrameTimes& times) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  char text[256];
  std::snprintf(text, sizeof text,
                "%s  %.1f fps | step %.1f ms (%lld) | deform %.2f ms | upload %.2f ms | draw "
                "%.1f ms",
                renderPath, frames_ / std::max(seconds, 1e-9), 1e3 * stepSeconds, steps,
                1e3 * times.deformSeconds, 1e3 * times.uploadSeconds,
                frames_ ? 1e3 * drawSeconds_ / frames_ : 0.0);
  start_ = now;
  frames_ = 0;
  drawSeconds_ = 0;
  return text;
}

}  // namespace tetskin::gui
