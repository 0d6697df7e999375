// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Text written into the XML files TetSkin writes by hand (.pvd, .pvtp).

#include <string>

namespace tetskin::detail {

// `text` as an XML attribute value: file names such as 'a&b_frames/...'
// are legal on disk, and array names may hold any character.
inline std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  return out;
}

}  // namespace tetskin::detail
