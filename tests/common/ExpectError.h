// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The checks of the errors bad input gets.

#include <gtest/gtest.h>

#include <string>

#include "tetskin/core/Error.h"

namespace tetskin::test {

// Expects `action()` to throw tetskin::Error naming `file` and `line` (0:
// none), reading "FILE:LINE: " (or "FILE: ") first, with `what` in its message.
template <typename Action>
void expectErrorAt(Action&& action, const std::string& file, long line, const std::string& what) {
  try {
    action();
    ADD_FAILURE() << "expected an error containing '" << what << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
    const std::string prefix = file + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

// The message (what()) of the tetskin::Error `action()` throws, or "no
// error": for tests that compare whole messages, or run on after one.
template <typename Action>
std::string errorText(Action&& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace tetskin::test
