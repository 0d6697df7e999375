// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/simulation/Scenario.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"

namespace tetskin {
namespace {

// A node's height: its coordinate along the simulation's up axis.
double height(const Simulation& sim, Index node) {
  return sim.restMesh().nodes(node, axisIndex(sim.options().up));
}

// The rest mesh's lowest height and its extent along the up axis.
std::pair<double, double> heightRange(const Simulation& sim) {
  const BoundingBox box = boundingBox(sim.restMesh().nodes);
  const int up = axisIndex(sim.options().up);
  return {box.min[up], box.extent()[up]};
}

// The base: nodes in the lowest share of the height (none for share 0).
std::vector<int> baseNodes(const Simulation& sim, double share) {
  if (share <= 0) return {};
  const auto [lowest, extent] = heightRange(sim);
  std::vector<int> nodes;
  for (Index v = 0; v < sim.restMesh().nodeCount(); ++v)
    if (height(sim, v) <= lowest + share * extent) nodes.push_back(static_cast<int>(v));
  return nodes;
}

class Sag : public Scenario {
 public:
  using Scenario::Scenario;
  const char* name() const override { return "sag"; }

 protected:
  std::vector<int> prepare(Simulation& sim) override { return baseNodes(sim, p_.baseShare); }
  void drive(Simulation&, double, Points3&) override {}
};

class Wobble : public Sag {
 public:
  using Sag::Sag;
  const char* name() const override { return "wobble"; }

 protected:
  void drive(Simulation&, double time, Points3& forces) override {
    forces += pushed_ * std::sin(2 * M_PI * p_.pushFrequency * time);
  }
  std::vector<int> prepare(Simulation& sim) override {
    std::vector<int> fixed = Sag::prepare(sim);
    const auto [lowest, extent] = heightRange(sim);
    const Eigen::VectorXd mass = sim.nodeMasses();
    // Sideways: x for y-up, as the y-up frame's x reads for the up axis.
    const Eigen::RowVector3d sideways =
        (fromYUp(sim.options().up) * Eigen::Vector3d::UnitX()).transpose();
    pushed_ = Points3::Zero(sim.restMesh().nodeCount(), 3);
    // The upper 40%, weighted by height so the push bends rather than shears.
    for (Index v = 0; v < pushed_.rows(); ++v) {
      const double t = (height(sim, v) - lowest) / extent;
      if (t > 0.6) pushed_.row(v) = mass[v] * p_.pushAcceleration * (t - 0.6) / 0.4 * sideways;
    }
    return fixed;
  }

 private:
  Points3 pushed_;
};

class Drop : public Scenario {
 public:
  using Scenario::Scenario;
  const char* name() const override { return "drop"; }

 protected:
  void drive(Simulation&, double, Points3&) override {}
  std::vector<int> prepare(Simulation& sim) override {
    Points3 lifted = sim.restMesh().nodes;
    lifted.col(axisIndex(sim.options().up)).array() += p_.dropHeight * heightRange(sim).second;
    sim.setPositions(lifted);
    return {};
  }
};

// Nothing held but what the parameters hold, nothing pushed: the body as
// placed, under gravity and its loads (a scene's body).
class Free : public Scenario {
 public:
  using Scenario::Scenario;
  const char* name() const override { return "free"; }

 protected:
  void drive(Simulation&, double, Points3&) override {}
  std::vector<int> prepare(Simulation&) override { return {}; }
};

class Twist : public Sag {
 public:
  using Sag::Sag;
  const char* name() const override { return "twist"; }

 protected:
  void drive(Simulation& sim, double time, Points3& forces) override;
  std::vector<int> prepare(Simulation& sim) override {
    const auto [lowest, extent] = heightRange(sim);
    std::vector<int> fixed = baseNodes(sim, p_.baseShare);
    top_.clear();
    for (Index v = 0; v < sim.restMesh().nodeCount(); ++v)
      if (height(sim, v) >= lowest + 0.85 * extent) top_.push_back(static_cast<int>(v));
    fixed.insert(fixed.end(), top_.begin(), top_.end());
    axis_ = boundingBox(sim.restMesh().nodes).center();
    return fixed;
  }

 private:
  std::vector<int> top_;
  Eigen::Vector3d axis_;
};

void Twist::drive(Simulation& sim, double time, Points3&) {
  const double h = sim.options().timeStep;
  const double share = std::min((time + h) / p_.twistSeconds, 1.0);
  const Eigen::AngleAxisd turn(share * p_.twistDegrees * M_PI / 180.0, upVector(sim.options().up));
  Points3 targets(static_cast<Index>(top_.size()), 3);
  for (std::size_t i = 0; i < top_.size(); ++i) {
    const Eigen::Vector3d p = sim.restMesh().nodes.row(top_[i]).transpose();
    targets.row(static_cast<Index>(i)) = (axis_ + turn * (p - axis_)).transpose();
  }
  sim.setKinematicTargets(top_, targets);
}

void validateScenarioParameters(const ScenarioParameters& p) {
  using namespace scenario_option;
  for (const auto& [option, value] :
       {std::pair{&kBaseShare, p.baseShare}, std::pair{&kPushAcceleration, p.pushAcceleration},
        std::pair{&kPushFrequency, p.pushFrequency}, std::pair{&kDropHeight, p.dropHeight},
        std::pair{&kTwistDegrees, p.twistDegrees}, std::pair{&kTwistSeconds, p.twistSeconds}})
    if (const auto problem = option->problem(value)) throw Error(*problem);
  if (!p.loads.allFinite()) throw Error("the loads must be finite");
  if (!p.loadCurve.empty() && p.loads.size() == 0 && p.surfaceLoads.empty())
    throw Error("a load curve scales the loads, but there are none");
  // (Infinite: the whole run.)
  if (!(p.loadSeconds > 0))
    throw Error("the time the loads act must be > 0, got " + formatNumber(p.loadSeconds));
}

}  // namespace

void Scenario::setUp(Simulation& sim) {
  if (p_.loads.size() > 0 && p_.loads.rows() != sim.restMesh().nodeCount())
    throw Error("the loads are for " + std::to_string(p_.loads.rows()) +
                " nodes, but the level has " + std::to_string(sim.restMesh().nodeCount()));
  std::vector<int> fixed = prepare(sim);
  fixed.insert(fixed.end(), p_.fixedNodes.begin(), p_.fixedNodes.end());
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  sim.setFixedNodes(fixed);
  sim.setSurfaceLoads(p_.surfaceLoads);
}

void Scenario::beforeStep(Simulation& sim, double time) {
  const bool loaded = p_.loads.size() > 0 && time < p_.loadSeconds;
  if (loaded)
    forces_ = p_.loadCurve.factorAt(time) * p_.loads;  // (same size: no allocation)
  else
    forces_.setZero(sim.restMesh().nodeCount(), 3);
  drive(sim, time, forces_);
  sim.setExternalForces(forces_);
  if (!p_.surfaceLoads.empty())
    sim.setSurfaceLoadFactor(time < p_.loadSeconds ? p_.loadCurve.factorAt(time) : 0.0);
}

std::vector<int> fixedWithNodesInBox(const std::vector<int>& held, const Points3& restNodes,
                                     const BoundingBox& box) {
  if (box.empty())
    throw Error("its minimum " + commaSeparated(box.min) + " exceeds its maximum " +
                commaSeparated(box.max) + " along an axis");
  const std::vector<int> inside = pointsInBox(restNodes, box);
  if (inside.empty()) {
    const BoundingBox level = boundingBox(restNodes);
    throw Error("no node of the level lies in " + commaSeparated(box.min) + " .. " +
                commaSeparated(box.max) + " (the level spans " + commaSeparated(level.min) +
                " .. " + commaSeparated(level.max) + ")");
  }
  std::vector<int> both;
  std::set_union(held.begin(), held.end(), inside.begin(), inside.end(), std::back_inserter(both));
  return both;
}

std::array<ScenarioField, 6> scenarioFields() {
  using namespace scenario_option;
  using P = ScenarioParameters;
  return {{{&kBaseShare, &P::baseShare, ScenarioParameter::BaseShare},
           {&kPushAcceleration, &P::pushAcceleration, ScenarioParameter::PushAcceleration},
           {&kPushFrequency, &P::pushFrequency, ScenarioParameter::PushFrequency},
           {&kDropHeight, &P::dropHeight, ScenarioParameter::DropHeight},
           {&kTwistDegrees, &P::twistDegrees, ScenarioParameter::TwistDegrees},
           {&kTwistSeconds, &P::twistSeconds, ScenarioParameter::TwistSeconds}}};
}

std::vector<std::string> scenariosReading(ScenarioParameter parameter) {
  // (Sag reads the base only; wobble and twist are sag with a push or a
  // turned top; drop has no base.)
  switch (parameter) {
    case ScenarioParameter::BaseShare:
      return {"wobble", "twist", "sag"};
    case ScenarioParameter::PushAcceleration:
    case ScenarioParameter::PushFrequency:
      return {"wobble"};
    case ScenarioParameter::DropHeight:
      return {"drop"};
    case ScenarioParameter::TwistDegrees:
    case ScenarioParameter::TwistSeconds:
      return {"twist"};
  }
  return {};
}

bool scenarioReads(std::string_view name, ScenarioParameter parameter) {
  const std::vector<std::string> readers = scenariosReading(parameter);
  return std::find(readers.begin(), readers.end(), name) != readers.end();
}

std::string notReadBy(std::string_view name, ScenarioParameter parameter) {
  const std::vector<std::string> scenarios = scenariosReading(parameter);
  std::string text = "applies to the ";
  for (std::size_t i = 0; i < scenarios.size(); ++i)
    text += (i == 0 ? "" : i + 1 == scenarios.size() ? " and " : ", ") + scenarios[i];
  return text + " scenario" + (scenarios.size() > 1 ? "s" : "") + ", not to " + std::string(name);
}

SimulationOptions scenarioOptions(std::string_view name, SimulationOptions options,
                                  const TetMesh& rest) {
  if (name == "drop" && !options.floorHeight)
    options.floorHeight = boundingBox(rest.nodes).min[axisIndex(options.up)];
  return options;
}

std::string nodesBelowFloor(const Simulation& sim) {
  const std::optional<double> floor = sim.options().floorHeight;
  if (!floor) return {};
  const Points3 x = sim.state().positions;
  // (A node on the floor, where drop from height 0 puts the lowest, is not below.)
  const double tolerance = 1e-9 * boundingBox(x).diagonal();
  const UpAxis up = sim.options().up;
  const auto below = (x.col(axisIndex(up)).array() < *floor - tolerance).count();
  if (below == 0) return {};
  return std::to_string(below) + " of " + std::to_string(x.rows()) +
         " nodes start below the floor at " + toString(up) + " = " + formatNumber(*floor) +
         "; contact pushes them up at once";
}

std::unique_ptr<Scenario> makeScenario(std::string_view name, const ScenarioParameters& p) {
  validateScenarioParameters(p);
  if (name == "wobble") return std::make_unique<Wobble>(p);
  if (name == "drop") return std::make_unique<Drop>(p);
  if (name == "twist") return std::make_unique<Twist>(p);
  if (name == "sag") return std::make_unique<Sag>(p);
  if (name == "free") return std::make_unique<Free>(p);
  throw Error("unknown scenario '" + std::string(name) + "' (known: " + listed(scenarioNames()) +
              ")");
}

bool isScenario(std::string_view name) {
  const std::vector<std::string> names = scenarioNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string> scenarioNames() {
  return {"wobble", "drop", "twist", "sag", "free"};
}

}  // namespace tetskin
