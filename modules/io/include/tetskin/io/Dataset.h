// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A dataset on disk: OUT.json + OUT.node + OUT.ele, all levels in one node and
// one element file, coarsest first.

#include <filesystem>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/io/DatasetConfig.h"

namespace tetskin {

struct Dataset {
  DatasetConfig config;
  MultiLevelTetMesh mesh;
};

// Loads a dataset from its `.json` config; a `.node` or `.ele` path loads the
// pair, and a Gmsh `.msh` or MEDIT `.mesh` its tetrahedra (TetrahedraFile.h;
// the nodes no tetrahedron uses dropped, elements of the other orientation
// turned), as a one-level dataset with default settings. Validates the level ranges
// against the files, every node index, and (for the config) that the
// config's ranges match the files exactly. Any other extension is an error.
Dataset loadDataset(const std::filesystem::path& path);
// Whether loadDataset takes the file by its extension (.json, .node, .ele,
// .msh, .mesh).
bool isDatasetFile(const std::filesystem::path& path);
// The config a build writes for the output name OUT or OUT.json (any letter
// case): OUT.json, with OUT.node and OUT.ele beside it.
std::filesystem::path datasetConfigPath(std::filesystem::path output);

// Writes `<stem>.node`, `<stem>.ele` beside `jsonPath` (or the names already
// in the config), then the config, each atomically; the config comes last so
// it never names files that are not complete. Updates config.levels' ranges
// and file names from the mesh.
void saveDataset(const std::filesystem::path& jsonPath, Dataset& dataset);

// Resolves a level argument: 0 is the coarsest; a negative level counts
// from the finest (-1 the finest, -2 the one below it), as Python indexes;
// a level outside the dataset either way is an Error.
int resolveLevel(const MultiLevelTetMesh& mesh, int level);

// The level a command, a binding and a run take when none is given.
inline constexpr int kFinestLevel = -1;

// The level option of every command and keyword that picks one
// (OptionSchema.h): any whole number, resolved by resolveLevel.
inline constexpr NumberOption kLevelOption{
    "level",
    "--level",
    "",
    "the level",
    "dataset level: 0 = coarsest, -1 = finest (the default), -2 the one below it, ...",
    {},
    kFinestLevel};

}  // namespace tetskin
