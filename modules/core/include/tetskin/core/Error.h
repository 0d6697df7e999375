// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The one exception type of TetSkin. It names where the problem is (a file and
// line, or a file and an element) so the CLI can print `error: FILE:LINE: what`.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tetskin {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message);
  // line <= 0 means "no line": the message then reads `FILE: what`.
  Error(const std::string& file, long line, const std::string& message);

  const std::string& file() const { return file_; }
  long line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  long line_ = 0;
  std::string message_;
};

// A number as error messages show it: %g, six significant digits ("0.3",
// "-0.46803", "1e-07", "1e+30"; std::to_string would say "-0.000000" for a
// tiny negative volume and "0.000000" for 1e-7).
std::string formatNumber(double value);

// Throws Error "WHAT: ROWS rows for COUNT ITEMS" unless rows == count: the
// check of rows a kernel reads or writes where they lie (Points3Ref rows of
// a VTK array, say), which it cannot resize.
void requireRows(const std::string& what, std::int64_t rows, std::int64_t count,
                 const std::string& items);

}  // namespace tetskin
