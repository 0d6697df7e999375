// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The procedural fur texture of the report (section 5): a random hair per
// texel (or a gap), stored as a 3D RGBA texture whose third coordinate is the
// height above the skin, so every shell samples its own layer:
//  - alpha: 0 in gaps; a hair of length a is opaque at the root, grows more
//    transparent toward its tip (it thins out) and ends at height a, so
//    short ("low-alpha") hairs end early;
//  - colour: white with a slight per-hair variation, darker toward the root
//    (self-shadowing among the hairs).

#include <cstdint>
#include <vector>

namespace tetskin {

struct FurTextureOptions {
  int size = 128;               // texels along each side, [8, 4096]
  int layers = 32;              // heights sampled, [2, 256]
  double density = 0.6;         // probability that a texel carries a hair, [0, 1]
  std::uint32_t seed = 1;       // same seed, same texture
  double rootShade = 0.35;      // brightness at the root relative to the tip, [0, 1]
  double minHairLength = 0.35;  // hair lengths are uniform in [min, 1] (of the fur length)
};

struct FurTexture {
  int size = 0, layers = 0;
  std::vector<float> hairLength;   // size*size, 0 = gap
  std::vector<std::uint8_t> rgba;  // layers*size*size*4, layer-major (OpenGL 3D order)
  // Height of layer l's centre in (0, 1).
  double layerHeight(int l) const { return (l + 0.5) / layers; }
  std::uint8_t alpha(int x, int y, int layer) const {
    return rgba[4 * ((static_cast<std::size_t>(layer) * size + y) * size + x) + 3];
  }
};

// Throws Error on parameters out of range.
FurTexture generateFurTexture(const FurTextureOptions& options);

// Opacity of a hair of length `hairLength` at `height` (both in fur lengths):
// 1 at the root falling to 0 at its tip, 0 above it and in gaps.
double hairOpacity(double hairLength, double height);

}  // namespace tetskin
