// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/RunRequest.h"

#include <algorithm>

#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"

namespace tetskin {

void MaterialOverrides::set(const NumberOption& option, double value) {
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].option == &option) {
      values[i] = value;
      return;
    }
  throw Error(std::string(option.key) + ": is no material value");
}

ElasticMaterial MaterialOverrides::over(const ElasticMaterial& config, OptionNames names) const {
  ElasticMaterial material = config;
  const auto fields = materialFields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (values[i]) material.*fields[i].field = *values[i];
  // A config's values were checked as it was read: a problem now is a
  // given value's, named as its user wrote it.
  if (const auto problem = materialProblem(material))
    for (const MaterialField& field : fields)
      if (problem->key == field.option->key)
        throw Error(nameOf(*field.option, names) + ": " + problem->what);
  return material;
}

SimulationOptions defaultRunSettings() {
  SimulationOptions settings;
  settings.solver = kDefaultRunSolver;
  return settings;
}

RunSpec resolveRun(const RunRequest& request, const MultiLevelTetMesh& mesh,
                   const DatasetConfig& config) {
  if (request.level < 0 || request.level >= static_cast<int>(mesh.levels.size()))
    throw Error(request.datasetName + ": has no level " + std::to_string(request.level) +
                " (it has " + std::to_string(mesh.levels.size()) + ")");
  if (!isScenario(request.scenario))
    throw Error("unknown scenario '" + request.scenario + "' (known: " + listed(scenarioNames()) +
                ")");
  RunSpec spec;
  spec.level = request.level;
  spec.datasetName = request.datasetName;
  spec.scenario = request.scenario;
  spec.options = uprightAlong(request.up.value_or(config.up), request.settings);
  spec.options.material = request.material.over(config.elasticity, request.names);
  if (request.gravity) spec.options.gravity = *request.gravity;
  spec.options.floorHeight = request.floorHeight;
  spec.parameters = request.parameters;
  spec.initialVelocity = request.initialVelocity;
  spec.bodies = request.bodies;
  spec.options.materialRegions.clear();
  spec.options.skinCollisions.selfBodies.clear();
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    RunBody& body = spec.bodies[b];
    body.material = request.material.over(body.material, request.names);
    const ElasticMaterial& first = spec.bodies.front().material;
    if (body.material.massDamping != first.massDamping ||
        body.material.stiffnessDamping != first.stiffnessDamping)
      throw Error(body.name + ": its damping (" + formatNumber(body.material.massDamping) + ", " +
                  formatNumber(body.material.stiffnessDamping) + ") is not " +
                  spec.bodies.front().name + "'s (" + formatNumber(first.massDamping) + ", " +
                  formatNumber(first.stiffnessDamping) +
                  "): " + nameOf(material_option::kMassDamping, request.names) + " and " +
                  nameOf(material_option::kStiffnessDamping, request.names) +
                  " are one for all the bodies of a run");
    spec.options.materialRegions.push_back(
        {body.range.firstElement, body.range.elementCount, body.material});
    if (body.selfContact) spec.options.skinCollisions.selfBodies.push_back(static_cast<int>(b));
  }
  if (!spec.bodies.empty()) spec.options.material = spec.bodies.front().material;
  if (request.fixedBox) {
    const LevelRange& level = mesh.levels[static_cast<std::size_t>(request.level)];
    const Points3 restNodes = mesh.nodes.middleRows(level.firstNode, level.nodeCount);
    try {
      spec.parameters.fixedNodes =
          fixedWithNodesInBox(spec.parameters.fixedNodes, restNodes, *request.fixedBox);
    } catch (const Error& e) {
      throw Error(nameOf(scenario_option::kFixedBox, request.names) + ": " + e.what());
    }
  }
  if (!request.surfaceLoads.empty()) {
    const TetMesh level = extractLevel(mesh, request.level);
    for (const SurfaceLoadRequest& load : request.surfaceLoads)
      spec.parameters.surfaceLoads.push_back(selectSurfaceLoad(load, level));
  }
  return spec;
}

}  // namespace tetskin
