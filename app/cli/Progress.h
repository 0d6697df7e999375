// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Progress and report lines on stderr: a live "stage i/n, elapsed" line when
// stderr is a terminal, plain report lines otherwise, nothing with --quiet.

#include <chrono>
#include <string>

namespace tetskin::cli {

class Progress {
 public:
  explicit Progress(bool quiet);
  ~Progress();
  void update(const std::string& stage, std::size_t done, std::size_t total);
  void log(const std::string& line);

 private:
  void clearLine();
  bool quiet_;
  bool terminal_;
  bool lineShown_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tetskin::cli
