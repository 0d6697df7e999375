// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/fur/FurTexture.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "tetskin/core/Error.h"

namespace tetskin {

double hairOpacity(double hairLength, double height) {
  if (hairLength <= 0 || height >= hairLength) return 0;
  return std::sqrt(1.0 - std::max(height, 0.0) / hairLength);
}

FurTexture generateFurTexture(const FurTextureOptions& o) {
  auto fail = [](const std::string& what) { throw Error("fur texture: " + what); };
  if (o.size < 8 || o.size > 4096) fail("size must lie in [8, 4096]");
  if (o.layers < 2 || o.layers > 256) fail("layers must lie in [2, 256]");
  if (!(o.density >= 0 && o.density <= 1)) fail("density must lie in [0, 1]");
  if (!(o.rootShade >= 0 && o.rootShade <= 1)) fail("root shade must lie in [0, 1]");
  if (!(o.minHairLength > 0 && o.minHairLength <= 1))
    fail("minimum hair length must lie in (0, 1]");
  FurTexture t;
  t.size = o.size;
  t.layers = o.layers;
  const std::size_t texels = static_cast<std::size_t>(o.size) * static_cast<std::size_t>(o.size);
  t.hairLength.assign(texels, 0.0f);
  std::vector<float> tint(texels, 1.0f);
  // Our own integer-to-real mapping: std's distributions are not specified
  // bit for bit, and a seed must give the same texture everywhere.
  std::mt19937 random(o.seed);
  auto uniform = [&random] { return static_cast<double>(random() >> 8) * (1.0 / 16777216.0); };
  for (std::size_t i = 0; i < texels; ++i) {
    const bool hair = uniform() < o.density;
    const double length = o.minHairLength + (1.0 - o.minHairLength) * uniform();
    const double shade = 0.88 + 0.12 * uniform();  // white, slightly varied
    if (hair) t.hairLength[i] = static_cast<float>(length);
    tint[i] = static_cast<float>(shade);
  }
  t.rgba.resize(4 * texels * static_cast<std::size_t>(o.layers));
  for (int l = 0; l < o.layers; ++l) {
    const double h = t.layerHeight(l);
    const double brightness = o.rootShade + (1.0 - o.rootShade) * h;
    std::uint8_t* layer = t.rgba.data() + 4 * texels * static_cast<std::size_t>(l);
    for (std::size_t i = 0; i < texels; ++i) {
      const auto grey = static_cast<std::uint8_t>(std::lround(255.0 * brightness * tint[i]));
      layer[4 * i + 0] = layer[4 * i + 1] = layer[4 * i + 2] = grey;
      layer[4 * i + 3] =
          static_cast<std::uint8_t>(std::lround(255.0 * hairOpacity(t.hairLength[i], h)));
    }
  }
  return t;
}

}  // namespace tetskin
