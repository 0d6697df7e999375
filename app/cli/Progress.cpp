// SPDX-License-Identifier: AGPL-3.0-or-later
#include "Progress.h"

#include <unistd.h>

#include <cstdio>

namespace tetskin::cli {

Progress::Progress(bool quiet)
    : quiet_(quiet),
      terminal_(::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  clearLine();
}

void Progress::clearLine() {
  if (lineShown_) std::fputs("\r\033[K", stderr);
  lineShown_ = false;
}

void Progress::update(const std::string& stage, std::size_t done, std::size_t total) {
  if (quiet_ || !terminal_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r\033[K[%s] %zu/%zu  %.1f s", stage.c_str(), done, total, elapsed);
  std::fflush(stderr);
  lineShown_ = true;
}

void Progress::log(const std::string& line) {
  if (quiet_) return;
  clearLine();
  std::fprintf(stderr, "%s\n", line.c_str());
}

}  // namespace tetskin::cli
