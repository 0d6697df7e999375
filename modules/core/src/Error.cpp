// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/core/Error.h"

#include <cstdio>

namespace tetskin {
namespace {

std::string describe(const std::string& file, long line, const std::string& message) {
  if (file.empty()) return message;
  if (line <= 0) return file + ": " + message;
  return file + ":" + std::to_string(line) + ": " + message;
}

}  // namespace

Error::Error(const std::string& message) : std::runtime_error(message), message_(message) {}

Error::Error(const std::string& file, long line, const std::string& message)
    : std::runtime_error(describe(file, line, message)),
      file_(file),
      line_(line),
      message_(message) {}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void requireRows(const std::string& what, std::int64_t rows, std::int64_t count,
                 const std::string& items) {
  if (rows != count)
    throw Error(what + ": " + std::to_string(rows) + " rows for " + std::to_string(count) + " " +
                items);
}

}  // namespace tetskin
