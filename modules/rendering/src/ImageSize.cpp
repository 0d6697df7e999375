// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/ImageSize.h"

#include <charconv>

namespace tetskin {
namespace {

// A whole number written with digits only (no sign, no space) in range.
std::optional<int> imageEdge(std::string_view text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
    return std::nullopt;
  int edge = 0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), edge);
  if (error != std::errc{} || stop != text.data() + text.size()) return std::nullopt;
  if (edge < kMinImageEdge || edge > kMaxImageEdge) return std::nullopt;
  return edge;
}

}  // namespace

std::optional<ImageSize> parseImageSize(std::string_view text) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const std::optional<int> width = imageEdge(text.substr(0, x));
  const std::optional<int> height = imageEdge(text.substr(x + 1));
  if (!width || !height) return std::nullopt;
  return ImageSize{*width, *height};
}

std::string imageSizeProblem(std::string_view text) {
  if (parseImageSize(text)) return {};
  // (Appended piece by piece: GCC 12 warns falsely on "'" + std::string.)
  std::string problem = "'";
  problem.append(text).append("' is not WIDTHxHEIGHT with both in [");
  problem.append(std::to_string(kMinImageEdge)).append(", ");
  return problem.append(std::to_string(kMaxImageEdge)).append("]");
}

std::string toString(ImageSize size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

}  // namespace tetskin
