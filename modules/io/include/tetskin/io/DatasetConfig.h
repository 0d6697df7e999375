// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The dataset config (`OUT.json`): which .node/.ele files hold the levels,
// where each level lies in them and where it came from, the defaults a
// viewer needs to show the object at once (scale, up axis, material,
// texture, surface, fur), and the body's elastic material for the
// simulation (elasticity).
// Reading validates every field; unknown fields are errors, so a typo never
// passes silently. Relative paths are relative to the config file.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/core/UpAxis.h"

namespace tetskin {

inline constexpr int kDatasetFormatVersion = 1;

struct Material {
  std::array<double, 3> color{0.85, 0.72, 0.62};  // linear RGB in [0, 1]
  double specular = 0.3;                          // [0, 1]
  double shininess = 30.0;                        // Phong exponent, (0, 1000]
};

enum class FurLighting { Velvet, KajiyaKay };

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
const char* toString(FurLighting lighting);
FurLighting parseFurLighting(std::string_view name);  // throws Error

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

struct LevelSource {
  std::string input;   // surface file the level was meshed from
  std::string mesher;  // "tetgen", "netgen", or what else produced it
  double quality = 0;  // TetGen radius-edge bound, or Netgen fineness preset index
  // The element size bound it was meshed under (build --size-to-targets):
  // TetGen's volume bound (-a) or Netgen's edge bound (maxh); 0: none.
  double sizeBound = 0;
};

struct LevelConfig {
  LevelRange range;
  LevelSource source;
  std::map<std::string, double> statistics;  // e.g. min_dihedral_deg
};

struct DatasetConfig {
  int version = kDatasetFormatVersion;
  std::filesystem::path nodeFile;  // as written in the config
  std::filesystem::path eleFile;
  std::vector<LevelConfig> levels;  // 0 = coarsest
  double scale = 1.0;
  UpAxis up = UpAxis::Y;  // `up`: "x", "y" or "z" (optional; y without it)
  Material material;
  std::optional<std::filesystem::path> texture;
  std::optional<std::filesystem::path> surface;
  FurParameters fur;
  // The `elasticity` section (every key optional; a config without it gets
  // the defaults): what `simulate`, `render --frames` and the GUI simulate
  // unless told otherwise.
  ElasticMaterial elasticity;
  nlohmann::json provenance = nlohmann::json::object();

  // The directory of the config file; relative paths are resolved against it.
  std::filesystem::path directory;
  std::filesystem::path resolve(const std::filesystem::path& p) const;
};

// `sourceName` names the file in errors, `directory` is where it lives.
DatasetConfig parseDatasetConfig(std::string_view content, const std::string& sourceName,
                                 const std::filesystem::path& directory);
DatasetConfig readDatasetConfig(const std::filesystem::path& path);
void writeDatasetConfig(const std::filesystem::path& path, const DatasetConfig& config);

}  // namespace tetskin
