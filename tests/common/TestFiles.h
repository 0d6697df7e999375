// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Scratch files for tests: a fresh directory per test, removed afterwards.

#include <filesystem>
#include <string>
#include <string_view>

namespace tetskin::test {

class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Writes `content` byte for byte and returns the path.
  std::filesystem::path write(const std::string& name, std::string_view content) const;
  // Names of the entries in the directory, sorted.
  std::string listing() const;

 private:
  std::filesystem::path path_;
};

std::string readText(const std::filesystem::path& path);

}  // namespace tetskin::test
