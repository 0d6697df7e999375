// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/DatasetConfig.h"

namespace tetskin {
namespace {

constexpr std::string_view kConfig = R"({
  "format": "tetskin-dataset",
  "version": 1,
  "node_file": "bunny.node",
  "ele_file": "bunny.ele",
  "levels": [
    {"nodes": [0, 4], "elements": [0, 1],
     "source": {"input": "bunny.obj", "mesher": "tetgen", "quality": 2.0},
     "statistics": {"min_dihedral_deg": 12.5}},
    {"nodes": [4, 5], "elements": [1, 2]}
  ],
  "scale": 2.0,
  "material": {"color": [0.5, 0.25, 1.0], "specular": 0.5, "shininess": 40},
  "texture": "fur.png",
  "surface": "surfaces/bunny_64k.obj",
  "fur": {"enabled": true, "shells": 24, "length": 0.05, "density": 0.7,
          "texture_size": 256, "seed": 42},
  "provenance": {"tool": "test"}
})";

void expectConfigError(const std::string& content, const std::string& what, long line = 0) {
  test::expectErrorAt([&] { parseDatasetConfig(content, "d.json", "/data"); }, "d.json", line,
                      what);
}

std::string replaced(std::string_view text, const std::string& from, const std::string& to) {
  std::string s(text);
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

TEST(DatasetConfig, ReadsEveryField) {
  const DatasetConfig c = parseDatasetConfig(kConfig, "d.json", "/data");
  EXPECT_EQ(c.nodeFile, "bunny.node");
  ASSERT_EQ(c.levels.size(), 2u);
  EXPECT_EQ(c.levels[1].range, (LevelRange{4, 5, 1, 2}));
  EXPECT_EQ(c.levels[0].source.mesher, "tetgen");
  EXPECT_EQ(c.levels[0].statistics.at("min_dihedral_deg"), 12.5);
  EXPECT_EQ(c.scale, 2.0);
  EXPECT_EQ(c.material.color[1], 0.25);
  EXPECT_EQ(c.material.shininess, 40.0);
  EXPECT_EQ(c.texture, std::filesystem::path("fur.png"));
  EXPECT_EQ(c.resolve(*c.surface), std::filesystem::path("/data/surfaces/bunny_64k.obj"));
  EXPECT_EQ(c.resolve("/abs/x.obj"), std::filesystem::path("/abs/x.obj"));
  EXPECT_TRUE(c.fur.enabled);
  EXPECT_EQ(c.fur.shells, 24);
  EXPECT_EQ(c.fur.seed, 42u);
  EXPECT_EQ(c.provenance["tool"], "test");
}

TEST(DatasetConfig, OptionalFieldsTakeDefaults) {
  const DatasetConfig c = parseDatasetConfig(
      R"({"format":"tetskin-dataset","version":1,"node_file":"a.node","ele_file":"a.ele",
          "levels":[{"nodes":[0,4],"elements":[0,1]}], "texture": null})",
      "d.json", ".");
  EXPECT_EQ(c.scale, 1.0);
  EXPECT_FALSE(c.texture);
  EXPECT_FALSE(c.surface);
  EXPECT_FALSE(c.fur.enabled);
  EXPECT_EQ(c.material.specular, Material{}.specular);
}

TEST(DatasetConfig, WriteThenReadIsEqual) {
  test::ScratchDir dir;
  const DatasetConfig c = parseDatasetConfig(kConfig, "d.json", dir.path());
  writeDatasetConfig(dir / "d.json", c);
  const DatasetConfig back = readDatasetConfig(dir / "d.json");
  EXPECT_EQ(back.directory, dir.path());
  EXPECT_EQ(back.levels[0].range, c.levels[0].range);
  EXPECT_EQ(back.levels[1].range, c.levels[1].range);
  EXPECT_EQ(back.levels[0].source.input, c.levels[0].source.input);
  EXPECT_EQ(back.levels[0].statistics, c.levels[0].statistics);
  EXPECT_EQ(back.material.color, c.material.color);
  EXPECT_EQ(back.surface, c.surface);
  EXPECT_EQ(back.fur.textureSize, c.fur.textureSize);
  EXPECT_EQ(back.provenance, c.provenance);
}

// A level meshed under a size bound (build --size-to-targets) keeps it; a
// level without one writes none, so older configs stay as they were.
TEST(DatasetConfig, LevelSizeBoundIsOptionalAndRoundTrips) {
  const DatasetConfig plain = parseDatasetConfig(kConfig, "d.json", "/data");
  EXPECT_EQ(plain.levels[0].source.sizeBound, 0.0);
  const DatasetConfig sized = parseDatasetConfig(
      replaced(kConfig, R"("quality": 2.0})", R"("quality": 2.0, "size_bound": 0.0025})"), "d.json",
      "/data");
  EXPECT_EQ(sized.levels[0].source.sizeBound, 0.0025);
  test::ScratchDir dir;
  writeDatasetConfig(dir / "sized.json", sized);
  EXPECT_EQ(readDatasetConfig(dir / "sized.json").levels[0].source.sizeBound, 0.0025);
  writeDatasetConfig(dir / "plain.json", plain);
  EXPECT_EQ(test::readText(dir / "plain.json").find("size_bound"), std::string::npos);
  expectConfigError(replaced(kConfig, R"("quality": 2.0})", R"("quality": 2.0, "size_bound": -1})"),
                    "/levels/0/source/size_bound: must lie in");
}

TEST(DatasetConfig, InvalidFieldsNameTheirJsonPointer) {
  expectConfigError(replaced(kConfig, R"("version": 1)", R"("version": 2)"), "/version:");
  expectConfigError(replaced(kConfig, R"("format": "tetskin-dataset")", R"("format": "x")"),
                    "/format:");
  expectConfigError(replaced(kConfig, R"("node_file": "bunny.node",)", ""),
                    "/node_file: is missing");
  expectConfigError(replaced(kConfig, R"("nodes": [4, 5])", R"("nodes": [4, -5])"),
                    "/levels/1/nodes: must be [first, count]");
  expectConfigError(replaced(kConfig, R"("scale": 2.0)", R"("scale": 0)"), "/scale: must lie in");
  expectConfigError(replaced(kConfig, R"("specular": 0.5)", R"("specular": 1.5)"),
                    "/material/specular");
  expectConfigError(replaced(kConfig, R"([0.5, 0.25, 1.0])", R"([0.5, 0.25])"), "/material/color");
  expectConfigError(replaced(kConfig, R"("shells": 24)", R"("shells": 0)"), "/fur/shells");
  expectConfigError(replaced(kConfig, R"("seed": 42)", R"("seed": 4.5)"),
                    "/fur/seed: must be an integer");
  expectConfigError(replaced(kConfig, R"("scale": 2.0)", R"("scael": 2.0)"),
                    "/scael: is not a known field");
  expectConfigError(replaced(kConfig, R"("levels": [)", R"("levels": [], "x": [)"),
                    "/levels: must be a non-empty array");
  expectConfigError(replaced(kConfig, R"("min_dihedral_deg": 12.5)", R"("min_dihedral_deg": "a")"),
                    "/levels/0/statistics/min_dihedral_deg");
}

TEST(DatasetConfig, FurSectionOptionalFieldsDefaultAndRoundTrip) {
  const DatasetConfig plain = parseDatasetConfig(kConfig, "d.json", "/data");
  EXPECT_EQ(plain.fur.lighting, FurLighting::Velvet);  // absent: defaults
  EXPECT_FALSE(plain.fur.fins);
  EXPECT_TRUE(plain.fur.adaptiveShells);
  EXPECT_FALSE(plain.fur.colorTexture);
  const std::string full = replaced(
      kConfig, R"("seed": 42})",
      R"("seed": 42, "texture_repeats": 3.5, "root_shade": 0.2, "drag": 0.1, "max_bend": 0.4,
          "lighting": "kajiya-kay", "velvet": 0.7, "base_darkening": 0.3, "fins": true,
          "adaptive_shells": false, "min_shells": 8, "color_texture": "mask.png"})");
  test::ScratchDir dir;
  const DatasetConfig c = parseDatasetConfig(full, "d.json", dir.path());
  EXPECT_EQ(c.fur.textureRepeats, 3.5);
  EXPECT_EQ(c.fur.rootShade, 0.2);
  EXPECT_EQ(c.fur.drag, 0.1);
  EXPECT_EQ(c.fur.maxBend, 0.4);
  EXPECT_EQ(c.fur.lighting, FurLighting::KajiyaKay);
  EXPECT_EQ(c.fur.velvet, 0.7);
  EXPECT_EQ(c.fur.baseDarkening, 0.3);
  EXPECT_TRUE(c.fur.fins);
  EXPECT_FALSE(c.fur.adaptiveShells);
  EXPECT_EQ(c.fur.minShells, 8);
  EXPECT_EQ(c.fur.colorTexture, std::filesystem::path("mask.png"));
  writeDatasetConfig(dir / "d.json", c);
  const DatasetConfig back = readDatasetConfig(dir / "d.json");
  EXPECT_EQ(back.fur.lighting, c.fur.lighting);
  EXPECT_EQ(back.fur.minShells, c.fur.minShells);
  EXPECT_EQ(back.fur.colorTexture, c.fur.colorTexture);
  EXPECT_EQ(back.fur.maxBend, c.fur.maxBend);
  EXPECT_EQ(back.fur.fins, c.fur.fins);
  expectConfigError(replaced(kConfig, R"("seed": 42})", R"("seed": 42, "lighting": "shiny"})"),
                    "/fur/lighting: unknown fur lighting 'shiny'");
  expectConfigError(replaced(kConfig, R"("seed": 42})", R"("seed": 42, "min_shells": 25})"),
                    "/fur/min_shells: must lie in [1, 24]");
  expectConfigError(replaced(kConfig, R"("seed": 42})", R"("seed": 42, "fins": 1})"),
                    "/fur/fins: must be true or false");
  expectConfigError(replaced(kConfig, R"("seed": 42})", R"("seed": 42, "fur_length": 1})"),
                    "/fur/fur_length: is not a known field");
}

// The body's material: every key optional (defaults), ranges checked by
// materialProblem and named by JSON pointer, written back in full.
TEST(DatasetConfig, ElasticitySectionDefaultsValidatesAndRoundTrips) {
  const DatasetConfig plain = parseDatasetConfig(kConfig, "d.json", "/data");
  EXPECT_EQ(plain.elasticity.youngsModulus, ElasticMaterial{}.youngsModulus);
  EXPECT_EQ(plain.elasticity.stiffnessDamping, ElasticMaterial{}.stiffnessDamping);

  const std::string soft =
      replaced(kConfig, R"("provenance")",
               R"("elasticity": {"youngs_modulus": 5e4, "poisson_ratio": -0.2, "density": 1000},
  "provenance")");
  const DatasetConfig c = parseDatasetConfig(soft, "d.json", "/data");
  EXPECT_EQ(c.elasticity.youngsModulus, 5e4);
  EXPECT_EQ(c.elasticity.poissonRatio, -0.2);
  EXPECT_EQ(c.elasticity.density, 1000.0);
  EXPECT_EQ(c.elasticity.massDamping, ElasticMaterial{}.massDamping);  // not given

  test::ScratchDir dir;
  writeDatasetConfig(dir / "d.json", c);
  const DatasetConfig back = readDatasetConfig(dir / "d.json");
  EXPECT_EQ(back.elasticity.youngsModulus, 5e4);
  EXPECT_EQ(back.elasticity.poissonRatio, -0.2);
  EXPECT_EQ(back.elasticity.density, 1000.0);
  EXPECT_EQ(back.elasticity.massDamping, c.elasticity.massDamping);
  EXPECT_EQ(back.elasticity.stiffnessDamping, c.elasticity.stiffnessDamping);

  expectConfigError(replaced(soft, R"("poisson_ratio": -0.2)", R"("poisson_ratio": 0.5)"),
                    "/elasticity/poisson_ratio: Poisson's ratio must lie in (-1, 0.5), got 0.5");
  expectConfigError(replaced(soft, R"("density": 1000)", R"("density": 0)"),
                    "/elasticity/density: density must be finite and positive, got 0");
  expectConfigError(replaced(soft, R"("youngs_modulus": 5e4)", R"("youngs_modulus": "5e4")"),
                    "/elasticity/youngs_modulus: must be a number");
  expectConfigError(replaced(soft, R"("density": 1000)", R"("densty": 1000)"),
                    "/elasticity/densty: is not a known field");
}

// The up axis: optional (y), "x", "y" or "z" in any letter case, written back.
TEST(DatasetConfig, UpAxisDefaultsValidatesAndRoundTrips) {
  EXPECT_EQ(parseDatasetConfig(kConfig, "d.json", "/data").up, UpAxis::Y);
  const std::string zUp = replaced(kConfig, R"("scale": 2.0,)", R"("scale": 2.0, "up": "Z",)");
  const DatasetConfig c = parseDatasetConfig(zUp, "d.json", "/data");
  EXPECT_EQ(c.up, UpAxis::Z);
  test::ScratchDir dir;
  writeDatasetConfig(dir / "d.json", c);
  EXPECT_NE(test::readText(dir / "d.json").find(R"("up": "z")"), std::string::npos);
  EXPECT_EQ(readDatasetConfig(dir / "d.json").up, UpAxis::Z);
  expectConfigError(replaced(zUp, R"("up": "Z")", R"("up": "-z")"),
                    R"(/up: must be "x", "y" or "z", found "-z")");
  expectConfigError(replaced(zUp, R"("up": "Z")", R"("up": 2)"), "/up: must be a non-empty string");
}

TEST(DatasetConfig, SyntaxErrorNamesTheLine) {
  expectConfigError(replaced(kConfig, R"("scale": 2.0,)", R"("scale": 2.0,,)"), "invalid JSON", 12);
  expectConfigError("", "invalid JSON", 1);
  expectConfigError("[1, 2]", "/: must be an object");
  // A number beyond a double: a clean error on its line (found by fuzz_config).
  expectConfigError(replaced(kConfig, R"("scale": 2.0,)", R"("scale": 2e999,)"),
                    "invalid JSON: number overflow parsing '2e999'", 12);
}

// The one check of the fur ranges (the config reader and render's options):
// defaults pass; the first parameter out of range is named with its value,
// min_shells against the shells in effect.
TEST(DatasetConfig, FurParameterProblemNamesTheFirstParameterOutOfRange) {
  FurParameters fur;
  EXPECT_FALSE(furParameterProblem(fur));
  fur.length = 0;
  fur.drag = 11;
  auto problem = furParameterProblem(fur);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->key, "length");
  EXPECT_EQ(problem->what, "must lie in (0, 1], found 0");
  fur = FurParameters{};
  fur.shells = 3;  // below the default min_shells 4
  problem = furParameterProblem(fur);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->key, "min_shells");
  EXPECT_EQ(problem->what, "must lie in [1, 3], found 4");
  fur.density = std::nan("");
  EXPECT_EQ(furParameterProblem(fur)->key, "density");
}

}  // namespace
}  // namespace tetskin
