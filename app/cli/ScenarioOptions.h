// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The scenario options of `tetskin simulate`: which scenario, its parameters
// (Scenario.h), nodes held still from a file, gravity and a floor.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/io/DatasetConfig.h"
#include "tetskin/session/RunRequest.h"
#include "tetskin/simulation/Scenario.h"

namespace tetskin::cli {

struct ScenarioArgs {
  std::string name = kDefaultScenario;
  ScenarioParameters parameters;
  std::filesystem::path fixedNodes;  // a node list (io NodeList.h), or empty
  std::vector<double> fixedBox;      // --fixed-box: min x, y, z, max x, y, z; empty: none
  std::filesystem::path loads;       // node forces (io NodeList.h), or empty
  std::filesystem::path loadCurve;   // scales the loads (io LoadCurveFile.h), or empty
  // One surface load: --pressure, --traction (x, y, z) on the faces of
  // --load-box (min x, y, z, max x, y, z) or --load-faces (a face set).
  std::optional<double> pressure;
  std::vector<double> traction, loadBox;
  std::filesystem::path loadFaces;
  std::vector<double> gravity;  // x, y, z; empty: the default
  std::optional<double> floor;  // height of a floor plane
  std::string up;               // --up: x, y or z; empty: the dataset's
};

// Adds --scenario, --up and the "Scenario" group of options to `cmd`.
void addScenarioOptions(CLI::App& cmd, ScenarioArgs& args);

// The up axis: --up, else the dataset config's.
UpAxis upAxisOf(const ScenarioArgs& args, const DatasetConfig& config);

// --scenario or the first option of the "Scenario" group given on the
// command line, if any.
std::optional<std::string> givenScenarioOption(const CLI::App& cmd);

// Sets in `request` what the command line gives of the scenario and its
// parameters (the numbers, the held nodes of --fixed-nodes, the loads and
// their curve read), the held box (--fixed-box), the surface load, gravity, the floor and
// the up axis, for a level of `nodeCount` nodes; the rest stays as
// `request` has it (the defaults, or a scene's values). Throws Error for an
// option of another scenario than the chosen one (e.g. --push-acceleration
// with drop): it would change nothing.
void fillScenario(const CLI::App& cmd, const ScenarioArgs& args, Index nodeCount,
                  RunRequest& request);

}  // namespace tetskin::cli
