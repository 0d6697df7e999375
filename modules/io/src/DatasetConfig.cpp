// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/DatasetConfig.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <tuple>

#include "TextLines.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/JsonFields.h"

namespace tetskin {
namespace {

using nlohmann::json;

LevelRange readRange(const JsonFields& level, const char* key, const std::string& file,
                     LevelRange r, bool nodes) {
  const json& pair = level.get(key);
  if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer() ||
      !pair[1].is_number_integer() || pair[0].get<long long>() < 0 || pair[1].get<long long>() <= 0)
    throw Error(file, 0,
                level.where(key) + ": must be [first, count] with first >= 0 and count > 0");
  (nodes ? r.firstNode : r.firstElement) = pair[0].get<Index>();
  (nodes ? r.nodeCount : r.elementCount) = pair[1].get<Index>();
  return r;
}

// {"max": x, "mean": y}: a one-sided distance.
std::pair<double, double> readDistance(const JsonFields& wrap, const char* key,
                                       const std::string& file) {
  JsonFields d(wrap.get(key), wrap.where(key), file);
  const double max = d.number("max", 0, 1e300);
  const double mean = d.number("mean", 0, 1e300);
  d.rejectUnknown();
  if (mean > max) d.fail(wrap.where(key) + "/mean", "must not exceed max");
  return {max, mean};
}

LevelWrap readWrap(const json& value, const std::string& pointer, const std::string& file) {
  JsonFields wrap(value, pointer, file);
  LevelWrap out;
  out.alpha = wrap.number("alpha", 0, 1e300, true);
  out.offset = wrap.number("offset", 0, 1e300, true);
  out.diagonal = wrap.number("diagonal", 0, 1e300, true);
  std::tie(out.inputToWrapMax, out.inputToWrapMean) = readDistance(wrap, "input_to_wrap", file);
  std::tie(out.wrapToInputMax, out.wrapToInputMean) = readDistance(wrap, "wrap_to_input", file);
  if (wrap.has("shell_thickness")) out.shellThickness = wrap.number("shell_thickness", 0, 1e300);
  wrap.optional("shell_thickness");
  wrap.rejectUnknown();
  return out;
}

LevelFidelity readFidelity(const json& value, const std::string& pointer, const std::string& file) {
  JsonFields fidelity(value, pointer, file);
  LevelFidelity out;
  out.diagonal = fidelity.number("diagonal", 0, 1e300, true);
  out.elementSize = fidelity.number("element_size", 0, 1e300, true);
  std::tie(out.inputToLevelMax, out.inputToLevelMean) =
      readDistance(fidelity, "input_to_level", file);
  std::tie(out.levelToInputMax, out.levelToInputMean) =
      readDistance(fidelity, "level_to_input", file);
  if (fidelity.has("bound")) {
    JsonFields bound(fidelity.get("bound"), fidelity.where("bound"), file);
    out.boundMax = bound.number("max", 0, 1e300);
    out.boundMean = bound.number("mean", 0, 1e300);
    bound.rejectUnknown();
  }
  fidelity.optional("bound");
  if (fidelity.has("faithful")) {
    const json& f = fidelity.get("faithful");
    if (!f.is_boolean()) fidelity.fail(fidelity.where("faithful"), "must be true or false");
    out.faithful = f.get<bool>();
  }
  fidelity.optional("faithful");
  fidelity.rejectUnknown();
  return out;
}

LevelConfig readLevel(const json& value, const std::string& pointer, const std::string& file) {
  JsonFields level(value, pointer, file);
  LevelConfig out;
  out.range = readRange(level, "nodes", file, out.range, true);
  out.range = readRange(level, "elements", file, out.range, false);
  if (level.has("source")) {
    JsonFields source(level.get("source"), pointer + "/source", file);
    out.source.input = source.optionalString("input").value_or("");
    out.source.mesher = source.optionalString("mesher").value_or("");
    if (source.has("quality")) out.source.quality = source.number("quality", 0, 1e6);
    source.optional("quality");
    if (source.has("size_bound")) out.source.sizeBound = source.number("size_bound", 0, 1e300);
    source.optional("size_bound");
    if (source.has("wrap"))
      out.source.wrap = readWrap(source.get("wrap"), pointer + "/source/wrap", file);
    source.optional("wrap");
    source.rejectUnknown();
  }
  level.optional("source");
  if (level.has("statistics")) {
    const json& stats = level.get("statistics");
    if (!stats.is_object()) level.fail(pointer + "/statistics", "must be an object");
    for (const auto& [key, v] : stats.items()) {
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        level.fail(pointer + "/statistics/" + key, "must be a finite number");
      out.statistics[key] = v.get<double>();
    }
  }
  level.optional("statistics");
  if (level.has("fidelity"))
    out.fidelity = readFidelity(level.get("fidelity"), pointer + "/fidelity", file);
  level.optional("fidelity");
  level.rejectUnknown();
  return out;
}

}  // namespace

std::filesystem::path DatasetConfig::resolve(const std::filesystem::path& p) const {
  return p.is_absolute() ? p : directory / p;
}

std::string describe(const LevelWrap& wrap) {
  const double d = wrap.diagonal > 0 ? wrap.diagonal : 1.0;
  char text[320];
  std::snprintf(text, sizeof text,
                "alpha %.3g%% and offset %.3g%% of the diagonal %.4g; input -> wrap: max %.3g "
                "(%.2g%%), mean %.3g (%.2g%%); wrap -> input: max %.3g (%.2g%%), mean %.3g "
                "(%.2g%%)",
                100 * wrap.alpha / d, 100 * wrap.offset / d, wrap.diagonal, wrap.inputToWrapMax,
                100 * wrap.inputToWrapMax / d, wrap.inputToWrapMean, 100 * wrap.inputToWrapMean / d,
                wrap.wrapToInputMax, 100 * wrap.wrapToInputMax / d, wrap.wrapToInputMean,
                100 * wrap.wrapToInputMean / d);
  std::string out = text;
  if (wrap.shellThickness > 0) {
    std::snprintf(text, sizeof text, "; a shell %.3g thick (%.2g%%)", wrap.shellThickness,
                  100 * wrap.shellThickness / d);
    out += text;
  }
  return out;
}

std::string describe(const LevelFidelity& f) {
  const double d = f.diagonal > 0 ? f.diagonal : 1.0;
  char text[320];
  std::snprintf(text, sizeof text,
                "input -> level: mean %.3g (%.2g%% of the diagonal), max %.3g (%.2g%%); "
                "level -> input: mean %.3g (%.2g%%), max %.3g (%.2g%%); element size %.3g",
                f.inputToLevelMean, 100 * f.inputToLevelMean / d, f.inputToLevelMax,
                100 * f.inputToLevelMax / d, f.levelToInputMean, 100 * f.levelToInputMean / d,
                f.levelToInputMax, 100 * f.levelToInputMax / d, f.elementSize);
  std::string out = text;
  if (!f.faithful) out += " (beyond its bound: accepted by the user)";
  return out;
}

DatasetConfig parseDatasetConfig(std::string_view content, const std::string& sourceName,
                                 const std::filesystem::path& directory) {
  const json root = parseJsonText(content, sourceName);
  JsonFields top(root, "", sourceName);
  DatasetConfig config;
  config.directory = directory;
  if (top.string("format") != "tetskin-dataset") top.fail("/format", "must be \"tetskin-dataset\"");
  config.version = static_cast<int>(top.integer("version", 1, 1000));
  if (config.version != kDatasetFormatVersion)
    top.fail("/version", "version " + std::to_string(config.version) +
                             " is not supported (this TetSkin reads version " +
                             std::to_string(kDatasetFormatVersion) + ")");
  config.nodeFile = top.string("node_file");
  config.eleFile = top.string("ele_file");
  const json& levels = top.get("levels");
  if (!levels.is_array() || levels.empty()) top.fail("/levels", "must be a non-empty array");
  for (std::size_t k = 0; k < levels.size(); ++k)
    config.levels.push_back(readLevel(levels[k], "/levels/" + std::to_string(k), sourceName));
  if (top.has("scale")) config.scale = top.number("scale", 0.0, 1e12, true);
  top.optional("scale");
  if (auto up = top.optionalString("up")) {
    const std::optional<UpAxis> axis = parseName<UpAxis>(*up);
    if (!axis) top.fail("/up", "must be \"x\", \"y\" or \"z\", found \"" + *up + "\"");
    config.up = *axis;
  }
  if (top.has("material")) {
    JsonFields m(top.get("material"), "/material", sourceName);
    const json& color = m.get("color");
    if (!color.is_array() || color.size() != 3)
      m.fail("/material/color", "must be [r, g, b] with values in [0, 1]");
    for (int k = 0; k < 3; ++k) {
      if (!color[k].is_number() || color[k].get<double>() < 0 || color[k].get<double>() > 1)
        m.fail("/material/color", "must be [r, g, b] with values in [0, 1]");
      config.material.color[k] = color[k].get<double>();
    }
    config.material.specular = m.number("specular", 0, 1);
    config.material.shininess = m.number("shininess", 0, 1000, true);
    m.rejectUnknown();
  }
  top.optional("material");
  if (auto t = top.optionalString("texture")) config.texture = *t;
  if (auto s = top.optionalString("surface")) config.surface = *s;
  if (top.has("fur")) {
    JsonFields f(top.get("fur"), "/fur", sourceName);
    const json& enabled = f.get("enabled");
    if (!enabled.is_boolean()) f.fail("/fur/enabled", "must be true or false");
    config.fur.enabled = enabled.get<bool>();
    // Types here; ranges once all are read (furParameterProblem).
    constexpr long long kAnyInt = std::numeric_limits<int>::max();
    FurParameters& p = config.fur;
    namespace fur = fur_option;
    p.shells = static_cast<int>(f.integer(fur::kShells.key, -kAnyInt, kAnyInt));
    p.length = f.anyNumber(fur::kLength.key);
    p.density = f.anyNumber(fur::kDensity.key);
    p.textureSize = static_cast<int>(f.integer(fur::kTextureSize.key, -kAnyInt, kAnyInt));
    p.seed = static_cast<std::uint32_t>(f.integer(fur::kSeed.key, 0, 0xffffffffLL));
    if (f.has(fur::kTextureRepeats.key)) p.textureRepeats = f.anyNumber(fur::kTextureRepeats.key);
    if (f.has(fur::kRootShade.key)) p.rootShade = f.anyNumber(fur::kRootShade.key);
    if (f.has(fur::kDrag.key)) p.drag = f.anyNumber(fur::kDrag.key);
    if (f.has(fur::kMaxBend.key)) p.maxBend = f.anyNumber(fur::kMaxBend.key);
    if (f.has(fur::kLighting.key)) {
      try {
        p.lighting = fromName<FurLighting>(f.string(fur::kLighting.key));
      } catch (const Error& e) {
        f.fail(f.where(fur::kLighting.key), e.what());
      }
    }
    if (f.has(fur::kVelvet.key)) p.velvet = f.anyNumber(fur::kVelvet.key);
    if (f.has(fur::kBaseDarkening.key)) p.baseDarkening = f.anyNumber(fur::kBaseDarkening.key);
    for (auto [key, flag] :
         {std::pair{fur::kFins.key, &p.fins}, {fur::kAdaptiveShells.key, &p.adaptiveShells}})
      if (f.has(key)) {
        if (!f.get(key).is_boolean()) f.fail(f.where(key), "must be true or false");
        *flag = f.get(key).get<bool>();
      }
    if (f.has(fur::kMinShells.key))
      p.minShells = static_cast<int>(f.integer(fur::kMinShells.key, -kAnyInt, kAnyInt));
    if (const auto problem = furParameterProblem(p)) f.fail("/fur/" + problem->key, problem->what);
    if (auto t = f.optionalString("color_texture")) p.colorTexture = *t;
    for (const char* key :
         {fur::kTextureRepeats.key, fur::kRootShade.key, fur::kDrag.key, fur::kMaxBend.key,
          fur::kLighting.key, fur::kVelvet.key, fur::kBaseDarkening.key, fur::kFins.key,
          fur::kAdaptiveShells.key, fur::kMinShells.key})
      f.optional(key);
    f.rejectUnknown();
  }
  top.optional("fur");
  if (top.has("elasticity")) {
    JsonFields e(top.get("elasticity"), "/elasticity", sourceName);
    ElasticMaterial& m = config.elasticity;
    // Types here; ranges once all are read (materialProblem).
    for (auto [key, value] : {std::pair{"youngs_modulus", &m.youngsModulus},
                              {"poisson_ratio", &m.poissonRatio},
                              {"density", &m.density},
                              {"mass_damping", &m.massDamping},
                              {"stiffness_damping", &m.stiffnessDamping}}) {
      if (e.has(key)) *value = e.anyNumber(key);
      e.optional(key);
    }
    if (const auto problem = materialProblem(m))
      e.fail("/elasticity/" + problem->key, problem->what);
    e.rejectUnknown();
  }
  top.optional("elasticity");
  if (top.has("provenance")) {
    config.provenance = top.get("provenance");
    if (!config.provenance.is_object()) top.fail("/provenance", "must be an object");
  }
  top.optional("provenance");
  top.rejectUnknown();
  return config;
}

DatasetConfig readDatasetConfig(const std::filesystem::path& path) {
  const std::string content = detail::readWholeFile(path);
  return parseDatasetConfig(content, path.string(), path.parent_path());
}

void writeDatasetConfig(const std::filesystem::path& path, const DatasetConfig& config) {
  json root;
  root["format"] = "tetskin-dataset";
  root["version"] = config.version;
  root["node_file"] = config.nodeFile.generic_string();
  root["ele_file"] = config.eleFile.generic_string();
  root["levels"] = json::array();
  for (const LevelConfig& level : config.levels) {
    json l;
    l["nodes"] = {level.range.firstNode, level.range.nodeCount};
    l["elements"] = {level.range.firstElement, level.range.elementCount};
    l["source"] = {{"input", level.source.input},
                   {"mesher", level.source.mesher},
                   {"quality", level.source.quality}};
    if (level.source.input.empty()) l["source"].erase("input");
    if (level.source.mesher.empty()) l["source"].erase("mesher");
    if (level.source.sizeBound > 0) l["source"]["size_bound"] = level.source.sizeBound;
    if (const std::optional<LevelWrap>& w = level.source.wrap) {
      l["source"]["wrap"] = {
          {"alpha", w->alpha},
          {"offset", w->offset},
          {"diagonal", w->diagonal},
          {"input_to_wrap", {{"max", w->inputToWrapMax}, {"mean", w->inputToWrapMean}}},
          {"wrap_to_input", {{"max", w->wrapToInputMax}, {"mean", w->wrapToInputMean}}}};
      if (w->shellThickness > 0) l["source"]["wrap"]["shell_thickness"] = w->shellThickness;
    }
    if (!level.statistics.empty()) l["statistics"] = level.statistics;
    if (const std::optional<LevelFidelity>& f = level.fidelity) {
      l["fidelity"] = {
          {"diagonal", f->diagonal},
          {"element_size", f->elementSize},
          {"input_to_level", {{"max", f->inputToLevelMax}, {"mean", f->inputToLevelMean}}},
          {"level_to_input", {{"max", f->levelToInputMax}, {"mean", f->levelToInputMean}}},
          {"faithful", f->faithful}};
      if (f->boundMax > 0 || f->boundMean > 0)
        l["fidelity"]["bound"] = {{"max", f->boundMax}, {"mean", f->boundMean}};
    }
    root["levels"].push_back(l);
  }
  root["scale"] = config.scale;
  root["up"] = toString(config.up);
  root["material"] = {{"color", config.material.color},
                      {"specular", config.material.specular},
                      {"shininess", config.material.shininess}};
  root["texture"] = config.texture ? json(config.texture->generic_string()) : json(nullptr);
  root["surface"] = config.surface ? json(config.surface->generic_string()) : json(nullptr);
  namespace fur = fur_option;
  root["fur"] = {{"enabled", config.fur.enabled},
                 {fur::kShells.key, config.fur.shells},
                 {fur::kLength.key, config.fur.length},
                 {fur::kDensity.key, config.fur.density},
                 {fur::kTextureSize.key, config.fur.textureSize},
                 {fur::kSeed.key, config.fur.seed},
                 {fur::kTextureRepeats.key, config.fur.textureRepeats},
                 {fur::kRootShade.key, config.fur.rootShade},
                 {fur::kDrag.key, config.fur.drag},
                 {fur::kMaxBend.key, config.fur.maxBend},
                 {fur::kLighting.key, toString(config.fur.lighting)},
                 {fur::kVelvet.key, config.fur.velvet},
                 {fur::kBaseDarkening.key, config.fur.baseDarkening},
                 {fur::kFins.key, config.fur.fins},
                 {fur::kAdaptiveShells.key, config.fur.adaptiveShells},
                 {fur::kMinShells.key, config.fur.minShells}};
  if (config.fur.colorTexture) root["fur"]["color_texture"] = config.fur.colorTexture->string();
  root["elasticity"] = {{"youngs_modulus", config.elasticity.youngsModulus},
                        {"poisson_ratio", config.elasticity.poissonRatio},
                        {"density", config.elasticity.density},
                        {"mass_damping", config.elasticity.massDamping},
                        {"stiffness_damping", config.elasticity.stiffnessDamping}};
  root["provenance"] = config.provenance;
  writeTextAtomically(path, [&](std::ostream& out) { out << root.dump(2) << '\n'; });
}

}  // namespace tetskin
