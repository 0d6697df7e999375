// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How a surface looks: its material and its fur. Plain values shared by the
// dataset config (io), which stores them, and the render paths and fur
// layer (rendering, fur), which draw with them; none of them owns the other.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "tetskin/core/OptionSchema.h"

namespace tetskin {

struct Material {
  std::array<double, 3> color{0.85, 0.72, 0.62};  // linear RGB in [0, 1]
  double specular = 0.3;                          // [0, 1]
  double shininess = 30.0;                        // Phong exponent, (0, 1000]
};

enum class FurLighting { Velvet, KajiyaKay };
template <>
struct EnumSchema<FurLighting> {
  static constexpr const char* what = "fur lighting";
  static constexpr EnumValue<FurLighting> values[] = {
      {FurLighting::Velvet, "velvet", "a soft sheen"},
      {FurLighting::KajiyaKay, "kajiya-kay", "strand highlights"}};
};

// The `fur` section; JSON keys in snake_case. Only `enabled`, `shells`,
// `length`, `density`, `texture_size` and `seed` are required.
struct FurParameters {
  bool enabled = false;
  int shells = 16;            // [1, 256]; the most shells drawn
  double length = 0.03;       // relative to the bounding-box diagonal, (0, 1]
  double density = 0.6;       // share of texels that carry a hair, [0, 1]
  int textureSize = 128;      // fur texture edge in texels, [8, 4096]
  std::uint32_t seed = 1;     // random seed of the fur texture
  double textureRepeats = 6;  // fur texture tiles across the bounding-box diagonal, (0, 1000]
  double rootShade = 0.35;    // brightness at the root (self-shadowing), [0, 1]
  double drag = 0.04;         // seconds of velocity the tips trail by (0 = static), [0, 10]
  double maxBend = 0.6;       // largest tip shift, in fur lengths, [0, 1]
  FurLighting lighting = FurLighting::Velvet;  // "velvet" or "kajiya-kay"
  double velvet = 0.5;          // how far the highlight is pushed off the mirror direction, [0, 1]
  double baseDarkening = 0.55;  // brightness of the skin under the fur, [0, 1]
  bool fins = false;            // silhouette fins (Lengyel et al. 2001)
  bool adaptiveShells = true;   // fewer shells when the fur is few pixels tall
  int minShells = 4;            // [1, shells]
  std::optional<std::filesystem::path> colorTexture;  // RGBA PNG over the surface's texcoords;
                                                      // alpha 0 = no fur (default: `texture`)
};

// The first numeric fur parameter outside its range (the ranges noted in
// FurParameters), as its config key and what is wrong, e.g. {"shells",
// "must lie in [1, 256], found 300"}; nullopt when all are in range. The one
// check of the ranges: the config reader and the command line's overrides
// both use it.
struct FurParameterProblem {
  std::string key;  // snake_case, as in the config's fur section
  std::string what;
};
std::optional<FurParameterProblem> furParameterProblem(const FurParameters& fur);

}  // namespace tetskin
