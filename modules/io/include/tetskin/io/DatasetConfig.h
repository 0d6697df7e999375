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

#include "tetskin/core/Appearance.h"
#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/core/UpAxis.h"

namespace tetskin {

inline constexpr int kDatasetFormatVersion = 1;

// How a level's input surface was made closed by alpha wrapping (build
// --wrap), and how far it lies from the input, both ways, in the input's
// units (the `wrap` object of a level's `source`). For an input decimated
// from a wrap, the distances are the decimated surface's.
struct LevelWrap {
  double alpha = 0;     // the wrap's alpha (absolute)
  double offset = 0;    // the wrap's offset (absolute)
  double diagonal = 0;  // the input's bounding-box diagonal: divide by it for fractions
  double inputToWrapMax = 0, inputToWrapMean = 0;  // over the input's vertices
  double wrapToInputMax = 0, wrapToInputMean = 0;  // over the wrap's vertices
  // The mean thickness of a shell made around an open sheet (0 when the
  // input enclosed a volume of its own).
  double shellThickness = 0;
};

// "alpha A, offset O; input -> wrap: max X (x% of the diagonal), mean Y
// (y%); wrap -> input: max ..., mean ...": what build, info and the GUI say
// of a wrap.
std::string describe(const LevelWrap& wrap);

// How faithfully a level's boundary follows the surface it stands for (the
// object's finest input as read), in the input's units (a level's
// `fidelity` object): one-sided distances both ways, sampled at the
// vertices (input -> level: how far the input's vertices lie from the
// level's boundary; level -> input: the other way), the level's element
// size h, and the bounds build held input -> level to (fractions of h,
// see tetskin/meshing/LevelFidelity.h; 0 when none was applied).
struct LevelFidelity {
  double diagonal = 0;     // of the input's bounding box: divide by it for fractions
  double elementSize = 0;  // h: the edge of the regular tetrahedron of the level's mean volume
  double inputToLevelMax = 0, inputToLevelMean = 0;
  double levelToInputMax = 0, levelToInputMean = 0;
  double boundMax = 0, boundMean = 0;  // on input -> level; 0: not checked
  // Within both bounds; false only where the user accepted an unfaithful
  // level (build --accept-unfaithful).
  bool faithful = true;
};

// "input -> level: mean X (x% of the diagonal), max Y (y%); level -> input:
// mean ..., max ...": what build, info, bind and the GUI say of a level.
std::string describe(const LevelFidelity& fidelity);

struct LevelSource {
  std::string input;   // surface file the level was meshed from
  std::string mesher;  // "tetgen", "netgen", or what else produced it
  double quality = 0;  // TetGen radius-edge bound, or Netgen fineness preset index
  // The element size bound it was meshed under (build --size-to-targets):
  // TetGen's volume bound (-a) or Netgen's edge bound (maxh); 0: none.
  double sizeBound = 0;
  std::optional<LevelWrap> wrap{};  // when the input was alpha-wrapped first
};

struct LevelConfig {
  LevelRange range;
  LevelSource source;
  std::map<std::string, double> statistics;  // e.g. min_dihedral_deg
  std::optional<LevelFidelity> fidelity{};   // measured by build; absent in older configs
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
