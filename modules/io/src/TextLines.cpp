// SPDX-License-Identifier: AGPL-3.0-or-later
#include "TextLines.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

namespace tetskin::detail {

std::string readWholeFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(path.string(), 0, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Error(path.string(), 0, "read error");
  return std::move(buffer).str();
}

TextLines::TextLines(std::string_view content, std::string sourceName, char commentChar)
    : content_(content), name_(std::move(sourceName)), comment_(commentChar) {
  // A UTF-8 byte order mark is harmless; skip it.
  if (content_.substr(0, 3) == "\xEF\xBB\xBF") position_ = 3;
}

bool TextLines::next() {
  while (position_ < content_.size()) {
    ++line_;
    std::size_t end = content_.find('\n', position_);
    if (end == std::string_view::npos) end = content_.size();
    std::string_view text = content_.substr(position_, end - position_);
    position_ = end + 1 > content_.size() ? content_.size() : end + 1;
    if (text.find('\0') != std::string_view::npos)
      fail("binary data (NUL byte) in a text file; is this a binary or UTF-16 file?");
    if (const std::size_t hash = text.find(comment_); hash != std::string_view::npos)
      text = text.substr(0, hash);
    tokens_.clear();
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      const std::size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      if (i > start) tokens_.push_back(text.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  tokens_.clear();
  return false;
}

void TextLines::fail(const std::string& message) const {
  throw Error(name_, line_, message);
}

void TextLines::expectTokens(std::size_t min, std::size_t max, const char* what) const {
  if (tokens_.size() < min || tokens_.size() > max) {
    std::string expected =
        min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
    fail(std::string(what) + ": expected " + expected + " values, found " +
         std::to_string(tokens_.size()));
  }
}

double TextLines::toDouble(std::string_view token, const char* what) const {
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range)
    fail(std::string(what) + " '" + std::string(token) + "' is out of range");
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
    fail(std::string(what) + " '" + std::string(token) + "' is not a number");
  if (!std::isfinite(value))
    fail(std::string(what) + " '" + std::string(token) + "' is not a finite number");
  return value;
}

std::array<double, 3> TextLines::toPoint(std::size_t first, const char* what) const {
  std::array<double, 3> p{};
  for (std::size_t k = 0; k < 3; ++k) p[k] = toDouble(tokens_[first + k], "coordinate");
  const std::string problem = coordinateProblem(Eigen::RowVector3d(p[0], p[1], p[2]));
  if (!problem.empty()) fail(std::string(what) + " " + problem);
  return p;
}

long long TextLines::toInteger(std::string_view token, const char* what) const {
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  long long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range)
    fail(std::string(what) + " '" + std::string(token) + "' is out of range");
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
    fail(std::string(what) + " '" + std::string(token) + "' is not an integer");
  return value;
}

void TextLines::checkCount(long long count, std::size_t minBytesPerItem, const char* what) const {
  if (count < 0) fail(std::string(what) + " " + std::to_string(count) + " is negative");
  if (static_cast<unsigned long long>(count) > remainingBytes() / minBytesPerItem)
    fail(std::string(what) + " " + std::to_string(count) +
         " is more than the rest of the file can hold (truncated or corrupt file?)");
}

}  // namespace tetskin::detail
