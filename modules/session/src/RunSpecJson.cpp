// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/session/RunSpecJson.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "tetskin/simulation/LinearSolvers.h"

namespace tetskin {
namespace {

// A number, or null where JSON has none (infinity: "for ever").
nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json rows(const Points3& points) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    out.push_back({points(i, 0), points(i, 1), points(i, 2)});
  return out;
}

nlohmann::json parametersJson(const ScenarioParameters& p) {
  nlohmann::json out;
  for (const ScenarioField& f : scenarioFields()) out[f.option->key] = p.*f.field;
  out["fixed_nodes"] = p.fixedNodes;
  out["loads"] = rows(p.loads);
  nlohmann::json curve = nlohmann::json::array();
  for (const LoadCurve::Point& point : p.loadCurve.points())
    curve.push_back({point.time, point.factor});
  out["load_curve"] = {
      {"points", curve},
      {"after", p.loadCurve.after() == LoadCurve::After::Repeat ? "repeat" : "hold"}};
  out["load_seconds"] = number(p.loadSeconds);
  nlohmann::json surface = nlohmann::json::array();
  for (const SurfaceLoad& load : p.surfaceLoads) {
    nlohmann::json faces = nlohmann::json::array();
    for (Eigen::Index f = 0; f < load.faces.rows(); ++f)
      faces.push_back({load.faces(f, 0), load.faces(f, 1), load.faces(f, 2)});
    surface.push_back({{"pressure", load.pressure},
                       {"traction", {load.traction.x(), load.traction.y(), load.traction.z()}},
                       {"faces", faces}});
  }
  out["surface_loads"] = surface;
  return out;
}

nlohmann::json vector(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json obstaclesJson(const std::vector<Obstacle>& obstacles) {
  nlohmann::json out = nlohmann::json::array();
  for (const Obstacle& o : obstacles) {
    nlohmann::json motion = nlohmann::json::array();
    for (const PoseKey& key : o.motion)
      motion.push_back(
          {{"time", key.time},
           {"translation", vector(key.translation)},
           {"rotation", {key.rotation.w(), key.rotation.x(), key.rotation.y(), key.rotation.z()}}});
    const ObstaclePose& p = o.placement;
    out.push_back({{"name", o.name},
                   {"translation", vector(p.translation)},
                   {"rotation", {p.rotation.w(), p.rotation.x(), p.rotation.y(), p.rotation.z()}},
                   {"scale", p.scale},
                   {"motion", motion},
                   {"static_friction", o.staticFriction},
                   {"kinetic_friction", o.kineticFriction},
                   {"stiffness", o.stiffness}});
  }
  return out;
}

nlohmann::json materialJson(const ElasticMaterial& m) {
  nlohmann::json material;
  for (const MaterialField& f : materialFields()) material[f.option->key] = m.*f.field;
  return material;
}

// Each body's place in the level and the skin ([first, count]), its
// material, velocity and self-contact.
nlohmann::json bodiesJson(const std::vector<RunBody>& bodies) {
  nlohmann::json out = nlohmann::json::array();
  for (const RunBody& b : bodies)
    out.push_back({{"name", b.name},
                   {"nodes", {b.range.firstNode, b.range.nodeCount}},
                   {"elements", {b.range.firstElement, b.range.elementCount}},
                   {"skin_vertices", {b.range.firstVertex, b.range.vertexCount}},
                   {"material", materialJson(b.material)},
                   {"velocity", vector(b.velocity)},
                   {"self_contact", b.selfContact}});
  return out;
}

nlohmann::json optionsJson(const SimulationOptions& o) {
  namespace so = simulation_option;
  return {{"material", materialJson(o.material)},
          {so::kTimeStep.key, o.timeStep},
          {"gravity", vector(o.gravity)},
          {"up", toString(o.up)},
          {"floor_height", o.floorHeight ? nlohmann::json(*o.floorHeight) : nullptr},
          {so::kFloorStiffness.key, o.floorStiffness},
          {so::kFriction.key, o.friction},
          {"tangent", toString(o.tangent)},
          {"solver", toString(o.solver)},
          {so::kTolerance.key, o.tolerance},
          {so::kGuessSolutions.key, o.guessSolutions},
          {so::kCoarseReuse.key, o.coarseReuse},
          {"coarse_operators", toString(o.coarseOperators)},
          {"coarse_levels", toString(o.coarseLevels)},
          {"single_precision_cycle", o.singlePrecisionCycle},
          {"smoother", toString(o.smoother)},
          {so::kMaxIterations.key, o.maxIterations},
          {"custom_preconditioner", static_cast<bool>(o.preconditioner)},
          {so::kContactPoints.key, toString(o.contactPoints)},
          {"skin_collisions",
           {{"self", o.skinCollisions.self},
            {"thickness", o.skinCollisions.thickness},
            {"stiffness", o.skinCollisions.stiffness},
            {"static_friction", o.skinCollisions.staticFriction},
            {"kinetic_friction", o.skinCollisions.kineticFriction}}},
          {"obstacles", obstaclesJson(o.obstacles)}};
}

}  // namespace

std::string runSpecJson(const RunSpec& spec) {
  const nlohmann::json out = {{"dataset", spec.datasetName},
                              {"level", spec.level},
                              {"scenario", spec.scenario},
                              {"parameters", parametersJson(spec.parameters)},
                              {"initial_velocity", vector(spec.initialVelocity)},
                              {"bodies", bodiesJson(spec.bodies)},
                              {"options", optionsJson(spec.options)}};
  return out.dump(2);
}

}  // namespace tetskin
