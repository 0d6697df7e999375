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

// The fur's number parameters (OptionSchema.h): config keys, `render`
// flags ("" where it has none), help, ranges and defaults, read by
// FurParameters' defaults, furParameterProblem, the command line and the
// GUI's View dock.
namespace fur_option {
inline constexpr NumberOption kShells{
    "shells", "--fur-shells", "", "fur shells", "most shells drawn", between(1, 256), 16};
inline constexpr NumberOption kLength{"length",
                                      "--fur-length",
                                      "",
                                      "fur length",
                                      "fur length / bounding-box diagonal",
                                      between(0, 1, false, true),
                                      0.03};
inline constexpr NumberOption kDensity{
    "density", "--fur-density", "", "fur density", "share of texels with a hair", between(0, 1),
    0.6};
inline constexpr NumberOption kTextureSize{"texture_size",
                                           "--fur-texture-size",
                                           "",
                                           "fur texture size",
                                           "fur texture edge in texels",
                                           between(8, 4096),
                                           128};
inline constexpr NumberOption kTextureRepeats{"texture_repeats",
                                              "--fur-texture-repeats",
                                              "--fur-repeats",
                                              "fur texture repeats",
                                              "fur texture tiles across the diagonal",
                                              between(0, 1000, false, true),
                                              6};
inline constexpr NumberOption kRootShade{
    "root_shade",  "",  "", "fur root shade", "brightness at the root (self-shadowing)",
    between(0, 1), 0.35};
inline constexpr NumberOption kDrag{"drag",
                                    "--fur-drag",
                                    "",
                                    "fur drag",
                                    "seconds of velocity the tips trail by (0: static)",
                                    between(0, 10),
                                    0.04};
inline constexpr NumberOption kMaxBend{
    "max_bend", "", "", "fur bend", "largest tip shift, in fur lengths", between(0, 1), 0.6};
inline constexpr NumberOption kVelvet{"velvet",
                                      "--fur-velvet",
                                      "",
                                      "velvet",
                                      "highlight offset off the mirror direction",
                                      between(0, 1),
                                      0.5};
inline constexpr NumberOption kBaseDarkening{
    "base_darkening", "",  "", "base darkening", "brightness of the skin under the fur",
    between(0, 1),    0.55};
// At most `shells` (furParameterProblem checks [1, shells]).
inline constexpr NumberOption kMinShells{"min_shells",
                                         "--fur-min-shells",
                                         "",
                                         "fewest fur shells",
                                         "fewest shells when adaptive",
                                         between(1, 256),
                                         4};
inline constexpr NumberOption kSeed{"seed",
                                    "--fur-seed",
                                    "",
                                    "fur seed",
                                    "random seed of the fur texture",
                                    between(0, 4294967295.0),
                                    1};
inline constexpr SwitchOption kFins{"fins", "--fur-fins", "", "fur fins", "silhouette fins", false};
inline constexpr SwitchOption kAdaptiveShells{"adaptive_shells",
                                              "--fur-adaptive-shells",
                                              "--fur-adaptive",
                                              "adaptive fur shells",
                                              "fewer shells when the fur is few pixels tall",
                                              true};
inline constexpr EnumOption<FurLighting> kLighting{"lighting", "--fur-lighting",
                                                   "the fur lighting"};
}  // namespace fur_option

// The `fur` section; JSON keys in snake_case. Only `enabled`, `shells`,
// `length`, `density`, `texture_size` and `seed` are required.
struct FurParameters {
  bool enabled = false;
  int shells = static_cast<int>(fur_option::kShells.defaultValue);
  double length = fur_option::kLength.defaultValue;    // of the bounding-box diagonal
  double density = fur_option::kDensity.defaultValue;  // share of texels that carry a hair
  int textureSize = static_cast<int>(fur_option::kTextureSize.defaultValue);  // texels
  std::uint32_t seed =
      static_cast<std::uint32_t>(fur_option::kSeed.defaultValue);  // of the texture
  double textureRepeats = fur_option::kTextureRepeats.defaultValue;
  double rootShade = fur_option::kRootShade.defaultValue;  // brightness at the root
  double drag = fur_option::kDrag.defaultValue;            // seconds the tips trail by
  double maxBend = fur_option::kMaxBend.defaultValue;      // largest tip shift, fur lengths
  FurLighting lighting = FurLighting::Velvet;
  double velvet = fur_option::kVelvet.defaultValue;  // highlight off the mirror direction
  double baseDarkening = fur_option::kBaseDarkening.defaultValue;
  bool fins = fur_option::kFins.defaultValue;  // silhouette fins (Lengyel et al. 2001)
  bool adaptiveShells = fur_option::kAdaptiveShells.defaultValue;
  int minShells = static_cast<int>(fur_option::kMinShells.defaultValue);
  std::optional<std::filesystem::path> colorTexture;  // RGBA PNG over the surface's texcoords;
                                                      // alpha 0 = no fur (default: `texture`)
};

// The first numeric fur parameter outside its range (fur_option's), as its
// config key and what is wrong, e.g. {"shells",
// "must lie in [1, 256], found 300"}; nullopt when all are in range. The one
// check of the ranges: the config reader and the command line's overrides
// both use it.
struct FurParameterProblem {
  std::string key;  // snake_case, as in the config's fur section
  std::string what;
};
std::optional<FurParameterProblem> furParameterProblem(const FurParameters& fur);

}  // namespace tetskin
