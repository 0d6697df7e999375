// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What a user asks a run to be, as every front end fills it (the CLI from
// its flags, the GUI from its docks, Python from its keywords), and the one
// function that makes it a run: resolveRun applies the dataset's config
// (material, up axis), the defaults and every check. A default lives here
// or in the option's schema, never in a front end, so `tetskin simulate`,
// `render --frames`, `bench`, tetskin-gui and tetskin.Simulation run the
// same thing for the same request (tests/session/RunRequestTest.cpp and
// the front ends' parity test check it).

#include <array>
#include <optional>
#include <string>

#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/DatasetConfig.h"
#include "tetskin/session/SimulationSession.h"
#include "tetskin/session/SurfaceLoadSelection.h"
#include "tetskin/simulation/Scenario.h"
#include "tetskin/simulation/Simulation.h"

namespace tetskin {

// The solver a request runs when it names none: auto picks the faster of
// cg and multigrid on the running simulation. (SimulationOptions{} keeps
// cg, the library's choice for a program that sets up its own solves.)
inline constexpr SolverKind kDefaultRunSolver = SolverKind::Automatic;

// Material values given over the dataset config's elasticity, one per
// field of materialFields(), in its order; nullopt: the config's.
struct MaterialOverrides {
  std::array<std::optional<double>, 5> values;

  // Sets the value of the field whose option is `option` (one of
  // materialFields()'s).
  void set(const NumberOption& option, double value);
  // `config` with the given values over it. Throws Error naming the
  // option (as `names` says) whose value is out of its range.
  ElasticMaterial over(const ElasticMaterial& config, OptionNames names) const;
};

// The settings of a run that do not depend on the dataset: the time step,
// the solver and its settings, the floor's contact. Defaults: the
// schema's, and kDefaultRunSolver.
SimulationOptions defaultRunSettings();

struct RunRequest {
  std::string datasetName = "dataset";  // names the dataset in errors
  int level = 0;                        // a resolved level of the dataset
  std::string scenario = kDefaultScenario;
  // The scenario's numbers, the held node ids, the loads, their curve and
  // seconds (Scenario.h); the nodes in fixedBox are held too.
  ScenarioParameters parameters;
  std::optional<BoundingBox> fixedBox;
  // Pressures and tractions on faces of the level, selected as each says
  // (added to parameters.surfaceLoads, which may hold some already).
  std::vector<SurfaceLoadRequest> surfaceLoads;
  OptionNames names = OptionNames::Keys;  // how errors name the options
  MaterialOverrides material;
  std::optional<UpAxis> up;                // nullopt: the dataset config's
  std::optional<Eigen::Vector3d> gravity;  // nullopt: standard gravity down the up axis
  std::optional<double> floorHeight;       // along the up axis; nullopt: no floor
  Eigen::Vector3d initialVelocity = Eigen::Vector3d::Zero();  // every node's at the start
  // The time step, solver, tolerance, ... (the material, up, gravity and
  // floor in it are replaced by the fields above).
  SimulationOptions settings = defaultRunSettings();
  // Several bodies (a scene's; empty: the level is one body), each with
  // its material as its dataset and scene give it: `material`'s values go
  // over each body's instead of over the config's.
  std::vector<RunBody> bodies;
};

// The run `request` describes on `mesh` with `config`: the config's
// material under the given values, upright along the given or the config's
// up axis, the held box's nodes added, the surface loads' faces selected.
// Throws Error for a scenario that does not exist, a level that does not, a
// material value out of range, or a held box around no node of the level,
// each named as `names` says; for bodies whose damping differs (a run damps
// all its bodies alike); for a surface load selectSurfaceLoad refuses.
RunSpec resolveRun(const RunRequest& request, const MultiLevelTetMesh& mesh,
                   const DatasetConfig& config);

}  // namespace tetskin
