// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A strict line-by-line tokenizer for the text formats (OBJ, TetGen). It knows
// the source name and the line number, so every error it raises reads
// `FILE:LINE: what`.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tetskin::detail {

std::string readWholeFile(const std::filesystem::path& path);

class TextLines {
 public:
  // `commentChar` starts a comment that runs to the end of the line.
  TextLines(std::string_view content, std::string sourceName, char commentChar = '#');

  // Advances to the next line that has tokens; false at the end of the input.
  bool next();
  long lineNumber() const { return line_; }
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  std::size_t size() const { return tokens_.size(); }
  std::string_view operator[](std::size_t i) const { return tokens_[i]; }
  // Bytes after the current line: an upper bound for how many items can follow.
  std::size_t remainingBytes() const { return content_.size() - position_; }
  const std::string& sourceName() const { return name_; }

  [[noreturn]] void fail(const std::string& message) const;
  // Fails unless the current line has between min and max tokens.
  void expectTokens(std::size_t min, std::size_t max, const char* what) const;

  double toDouble(std::string_view token, const char* what) const;  // finite only
  // Tokens first..first+2 as a point's coordinates: finite, and within the
  // magnitude every mesh must keep (core's coordinateProblem); `what` names
  // the point ("vertex", "node") in the error.
  std::array<double, 3> toPoint(std::size_t first, const char* what) const;
  long long toInteger(std::string_view token, const char* what) const;
  // Fails when `count` items of at least `minBytesPerItem` bytes each cannot
  // fit in the rest of the input, so a corrupt header never allocates absurdly.
  void checkCount(long long count, std::size_t minBytesPerItem,
                  const char* what) const;  // 2 bytes: "0\n"

 private:
  std::string_view content_;
  std::string name_;
  char comment_;
  std::size_t position_ = 0;
  long line_ = 0;
  std::vector<std::string_view> tokens_;
};

}  // namespace tetskin::detail
