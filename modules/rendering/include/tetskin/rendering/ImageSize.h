// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The size of a rendered image or view as the command lines write it,
// "WIDTHxHEIGHT": one reading for `tetskin render`, `tetskin bench` and
// `tetskin-gui --size`.

#include <optional>
#include <string>
#include <string_view>

namespace tetskin {

struct ImageSize {
  int width = 0;
  int height = 0;
};

inline constexpr int kMinImageEdge = 16;
inline constexpr int kMaxImageEdge = 8192;

// Two whole numbers (digits only) joined by 'x', each in [kMinImageEdge,
// kMaxImageEdge]; anything else gives nothing.
std::optional<ImageSize> parseImageSize(std::string_view text);

// Why `text` is not an image size, for a message after the option's name:
// "'0x0' is not WIDTHxHEIGHT with both in [16, 8192]". Empty when it is one.
std::string imageSizeProblem(std::string_view text);

// "800x600": `size` as the command lines write it.
std::string toString(ImageSize size);

}  // namespace tetskin
