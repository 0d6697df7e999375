// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <limits>

#include "ExpectError.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"

namespace tetskin {
namespace {

TetMesh cubeCorner(double scale) {
  TetMesh m;
  m.nodes.resize(5, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  m.nodes *= scale;
  m.elements.resize(2, 4);
  m.elements << 0, 1, 2, 3, 4, 1, 3, 2;
  return m;
}

Dataset twoLevels() {
  Dataset d;
  appendLevel(d.mesh, cubeCorner(1.0));
  appendLevel(d.mesh, cubeCorner(2.0));
  d.config.levels.resize(2);
  d.config.levels[0].source = {"in.obj", "tetgen", 2.0};
  d.config.surface = "in.obj";
  return d;
}

TEST(Dataset, SaveThenLoadIsExact) {
  test::ScratchDir dir;
  Dataset d = twoLevels();
  saveDataset(dir / "d.json", d);
  EXPECT_EQ(dir.listing(), "d.ele\nd.json\nd.node\n");
  const Dataset back = loadDataset(dir / "d.json");
  EXPECT_EQ(back.mesh.nodes, d.mesh.nodes);
  EXPECT_EQ(back.mesh.elements, d.mesh.elements);
  EXPECT_EQ(back.mesh.levels, d.mesh.levels);
  EXPECT_EQ(back.config.levels[0].source.quality, 2.0);
  EXPECT_EQ(back.config.resolve(*back.config.surface), dir / "in.obj");
}

TEST(Dataset, ConfigRangesMustMatchTheFiles) {
  test::ScratchDir dir;
  Dataset d = twoLevels();
  saveDataset(dir / "d.json", d);
  nlohmann::json json = nlohmann::json::parse(test::readText(dir / "d.json"));
  json["levels"][1]["nodes"] = {5, 6};  // one node more than the files hold
  dir.write("d.json", json.dump());
  try {
    loadDataset(dir / "d.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), (dir / "d.json").string());
    EXPECT_NE(e.message().find("level 1"), std::string::npos) << e.what();
  }
}

TEST(Dataset, MissingNodeFileIsNamed) {
  test::ScratchDir dir;
  Dataset d = twoLevels();
  saveDataset(dir / "d.json", d);
  std::filesystem::remove(dir / "d.node");
  try {
    loadDataset(dir / "d.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), (dir / "d.node").string());
  }
}

// A surface where the dataset belongs (bind's arguments swapped) is named as
// not a dataset, not parsed as JSON.
TEST(Dataset, OtherExtensionsAreNotDatasets) {
  test::ScratchDir dir;
  const auto obj = dir.write("bunny.obj", "v 0 0 0\n");
  test::expectErrorAt(
      [&] { loadDataset(obj); }, obj.string(), 0,
      "is not a dataset (expected its .json config, a .node/.ele pair, a Gmsh .msh or a MEDIT "
      ".mesh)");
}

// A Gmsh mesh is a one-level dataset, as a .node/.ele pair is: its
// tetrahedra, the nodes no tetrahedron uses dropped, elements of the other
// orientation turned (the hand-written mesh below lists its one
// tetrahedron inverted, and a node only a point element uses).
TEST(Dataset, AGmshMeshIsAOneLevelDataset) {
  test::ScratchDir dir;
  const auto msh = dir.write("t.msh",
                             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n"
                             "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 7 7 7\n$EndNodes\n"
                             "$Elements\n2\n1 15 0 5\n2 4 0 2 1 3 4\n$EndElements\n");
  const Dataset d = loadDataset(msh);
  ASSERT_EQ(d.mesh.levels.size(), 1u);
  EXPECT_EQ(d.mesh.nodes.rows(), 4);
  ASSERT_EQ(d.mesh.elements.rows(), 1);
  EXPECT_NEAR(meshVolume(extractLevel(d.mesh, 0)), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(d.config.levels.front().source.mesher, "gmsh");
  EXPECT_EQ(d.config.levels.front().source.input, "t.msh");
}

// A MEDIT mesh likewise (its boundary triangles left out).
TEST(Dataset, AMeditMeshIsAOneLevelDataset) {
  test::ScratchDir dir;
  const auto mesh = dir.write("t.mesh",
                              "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n"
                              "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n7 7 7 0\n"
                              "Triangles\n1\n1 2 3 4\nTetrahedra\n1\n2 1 3 4 1\nEnd\n");
  const Dataset d = loadDataset(mesh);
  ASSERT_EQ(d.mesh.levels.size(), 1u);
  EXPECT_EQ(d.mesh.nodes.rows(), 4);
  ASSERT_EQ(d.mesh.elements.rows(), 1);
  EXPECT_NEAR(meshVolume(extractLevel(d.mesh, 0)), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(d.config.levels.front().source.mesher, "medit");
  EXPECT_TRUE(isDatasetFile("x.MESH"));
}

// What `tetskin build -o OUT` (and the GUI's build dialog) writes: OUT.json,
// whether OUT ends in .json (any letter case) or not.
TEST(Dataset, ConfigPathOfABuildsOutputName) {
  EXPECT_EQ(datasetConfigPath("out/bunny"), std::filesystem::path("out/bunny.json"));
  EXPECT_EQ(datasetConfigPath("out/bunny.json"), std::filesystem::path("out/bunny.json"));
  EXPECT_EQ(datasetConfigPath("out/bunny.JSON"), std::filesystem::path("out/bunny.json"));
  EXPECT_EQ(datasetConfigPath("bunny.v2"), std::filesystem::path("bunny.v2.json"));
}

TEST(Dataset, NodeElePairLoadsAsOneLevel) {
  test::ScratchDir dir;
  dir.write("m.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n");
  dir.write("m.ele", "2 4 0\n1 1 2 3 4\n2 5 2 4 3\n");
  const Dataset d = loadDataset(dir / "m.ele");
  ASSERT_EQ(d.mesh.levelCount(), 1);
  EXPECT_EQ(d.mesh.levels[0], (LevelRange{0, 5, 0, 2}));
  EXPECT_EQ(d.mesh.elements.row(1), Eigen::RowVector4i(4, 1, 3, 2));
  EXPECT_EQ(resolveLevel(d.mesh, -1), 0);
  EXPECT_THROW(resolveLevel(d.mesh, 1), Error);
  EXPECT_THROW(resolveLevel(d.mesh, -2), Error);  // one level: nothing below the finest
}

TEST(Dataset, NegativeLevelsCountFromTheFinest) {
  MultiLevelTetMesh mesh;  // (resolveLevel reads only the level count)
  mesh.levels.resize(3);
  EXPECT_EQ(resolveLevel(mesh, 0), 0);
  EXPECT_EQ(resolveLevel(mesh, 2), 2);
  EXPECT_EQ(resolveLevel(mesh, -1), 2);
  EXPECT_EQ(resolveLevel(mesh, -3), 0);
  for (int level : {3, -4, std::numeric_limits<int>::min()}) {
    try {
      resolveLevel(mesh, level);
      FAIL() << level;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), "level " + std::to_string(level) +
                                           " does not exist: the dataset has levels 0..2 (or "
                                           "-3..-1 counted from the finest)");
    }
  }
}

}  // namespace
}  // namespace tetskin
