// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/Dataset.h"

#include "tetskin/core/Error.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/io/TetrahedraFile.h"

namespace tetskin {
namespace {

// `mesh`, read from `path`, as a one-level dataset with default settings.
Dataset oneLevelDataset(const std::filesystem::path& path, const TetMesh& mesh) {
  Dataset dataset;
  appendLevel(dataset.mesh, mesh);
  dataset.config.directory = path.parent_path();
  LevelConfig level;
  level.range = dataset.mesh.levels.front();
  level.source.input = path.filename().string();
  dataset.config.levels.push_back(level);
  return dataset;
}

Dataset loadNodeElePair(const std::filesystem::path& path) {
  const NodeElePaths pair = nodeElePair(path);
  Dataset dataset = oneLevelDataset(path, readTetMesh(pair.node, pair.ele));
  dataset.config.nodeFile = pair.node.filename();
  dataset.config.eleFile = pair.ele.filename();
  return dataset;
}

// A Gmsh .msh or MEDIT .mesh: the nodes no tetrahedron uses dropped, the
// elements of the other orientation turned.
Dataset loadMeshFile(const std::filesystem::path& path) {
  TetrahedraFile read = readTetrahedraFile(path);
  removeUnreferencedNodes(read.mesh);
  orientElementsPositively(read.mesh);
  Dataset dataset = oneLevelDataset(path, read.mesh);
  dataset.config.levels.front().source.mesher = lowerExtension(path) == ".msh" ? "gmsh" : "medit";
  return dataset;
}

}  // namespace

bool isDatasetFile(const std::filesystem::path& path) {
  const std::string e = lowerExtension(path);
  return e == ".json" || isTetrahedraFile(path);
}

std::filesystem::path datasetConfigPath(std::filesystem::path output) {
  if (lowerExtension(output) == ".json") output.replace_extension();
  return output.string() + ".json";
}

Dataset loadDataset(const std::filesystem::path& path) {
  // Checked first: a surface given where the dataset belongs (arguments
  // swapped) would otherwise be parsed as JSON and fail on its first line.
  if (!isDatasetFile(path))
    throw Error(path.string(), 0,
                "is not a dataset (expected its .json config, a .node/.ele pair, a Gmsh .msh or a "
                "MEDIT .mesh)");
  if (lowerExtension(path) == ".node" || lowerExtension(path) == ".ele")
    return loadNodeElePair(path);
  if (lowerExtension(path) != ".json") return loadMeshFile(path);
  Dataset dataset;
  dataset.config = readDatasetConfig(path);
  const std::filesystem::path nodePath = dataset.config.resolve(dataset.config.nodeFile);
  const std::filesystem::path elePath = dataset.config.resolve(dataset.config.eleFile);
  const NodeFile nodes = readNode(nodePath);
  const EleFile ele = readEle(elePath);
  dataset.mesh.nodes = nodes.points;
  dataset.mesh.elements = ele.corners().array() + (ele.firstIndex - nodes.firstIndex);
  for (const LevelConfig& level : dataset.config.levels) dataset.mesh.levels.push_back(level.range);
  // Range errors are the config's fault, index errors the .ele file's.
  validateLevels(dataset.mesh, path.string());
  TetMesh all{dataset.mesh.nodes, dataset.mesh.elements};
  validateTetMesh(all, elePath.string(), /*requirePositiveVolume=*/false);
  return dataset;
}

void saveDataset(const std::filesystem::path& jsonPath, Dataset& dataset) {
  validateLevels(dataset.mesh, jsonPath.string());
  DatasetConfig& config = dataset.config;
  const std::string stem = jsonPath.stem().string();
  if (config.nodeFile.empty()) config.nodeFile = stem + ".node";
  if (config.eleFile.empty()) config.eleFile = stem + ".ele";
  config.directory = jsonPath.parent_path();
  config.levels.resize(dataset.mesh.levels.size());
  for (std::size_t k = 0; k < config.levels.size(); ++k)
    config.levels[k].range = dataset.mesh.levels[k];

  NodeFile nodes;
  nodes.points = dataset.mesh.nodes;
  EleFile ele;
  ele.elements = dataset.mesh.elements;
  writeNode(config.resolve(config.nodeFile), nodes);
  writeEle(config.resolve(config.eleFile), ele);
  writeDatasetConfig(jsonPath, config);
}

int resolveLevel(const MultiLevelTetMesh& mesh, int level) {
  const int count = mesh.levelCount();
  const long long resolved = level < 0 ? static_cast<long long>(count) + level : level;
  if (resolved < 0 || resolved >= count)
    throw Error("level " + std::to_string(level) + " does not exist: the dataset has levels 0.." +
                std::to_string(count - 1) + " (or -" + std::to_string(count) +
                "..-1 counted from the finest)");
  return static_cast<int>(resolved);
}

}  // namespace tetskin
