// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Ready-made experiments for `tetskin simulate --scenario`, upright along
// the simulation's up axis (SimulationOptions::up; y unless told otherwise):
//   wobble  base fixed, a periodic sideways push on the upper part (the
//           report's "animated deformation")
//   drop    the body starts above a floor and falls onto it
//   twist   base fixed, the top turned about the vertical axis
//   sag     base fixed, gravity only

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/LoadCurve.h"
#include "tetskin/simulation/Simulation.h"
#include "tetskin/simulation/SurfaceLoad.h"

namespace tetskin {

// The scenarios' number parameters (OptionSchema.h): their flags, help,
// ranges and defaults, read by ScenarioParameters' defaults, makeScenario's
// check, the command line and the GUI's Simulation dock.
namespace scenario_option {
inline constexpr NumberOption kBaseShare{
    "base_share",
    "--base-share",
    "--base",
    "the base share",
    "wobble, twist, sag: hold the nodes in this lowest share of the height still (0: none)",
    between(0, 1, true, false),
    0.1,
    "in [0, 1)"};
inline constexpr NumberOption kPushAcceleration{
    "push_acceleration",
    "--push-acceleration",
    "--push",
    "the push acceleration",
    "wobble: peak sideways acceleration of the push, m/s^2",
    NumberRange{},
    15};
inline constexpr NumberOption kPushFrequency{"push_frequency",
                                             "--push-frequency",
                                             "",
                                             "the push frequency",
                                             "wobble: push frequency, Hz",
                                             above(0),
                                             1.0,
                                             "finite and > 0"};
inline constexpr NumberOption kDropHeight{
    "drop_height",
    "--drop-height",
    "",
    "the drop height",
    "drop: start this share of the body's height above the floor",
    atLeast(0),
    0.3};
inline constexpr NumberOption kTwistDegrees{"twist_degrees",
                                            "--twist-degrees",
                                            "",
                                            "the twist angle",
                                            "twist: final angle of the top, degrees",
                                            NumberRange{},
                                            90};
inline constexpr NumberOption kTwistSeconds{"twist_seconds",
                                            "--twist-seconds",
                                            "",
                                            "the twist time",
                                            "twist: seconds to reach it",
                                            above(0),
                                            1.0,
                                            "finite and > 0"};

// The run's other options, for every scenario (OptionSchema.h: their keys,
// flags and words; each front end adds the form they take there).
inline constexpr ListOption kFixedNodes{
    "fixed_nodes", "--fixed-nodes", "the fixed nodes",
    "also hold these nodes of the level still (ids from 0: the point ids of its .vtu)"};
inline constexpr ListOption kFixedBox{
    "fixed_box", "--fixed-box", "the fixed box",
    "also hold still the nodes of the level inside this box, faces included, in the dataset's "
    "coordinates (a beam's end, say)"};
inline constexpr ListOption kLoads{"loads", "--loads", "the loads",
                                   "forces (newtons) on nodes of the level"};
// A surface load (SurfaceLoad.h): a pressure, a traction or both, on the
// boundary faces a box or a face set selects.
inline constexpr NumberOption kPressure{
    "pressure",
    "--pressure",
    "",
    "the pressure",
    "a pressure (Pa) on the loaded faces, along their inward normal as they deform (negative: "
    "suction)",
    NumberRange{},
    0};
inline constexpr ListOption kTraction{
    "traction", "--traction", "the traction",
    "a traction X, Y, Z (Pa: newtons per square metre of the loaded faces at rest), a fixed "
    "force per area"};
inline constexpr ListOption kLoadBox{
    "load_box", "--load-box", "the loaded faces' box",
    "the pressure and traction act on the faces of the level's boundary whose corners all lie "
    "in this box, faces included"};
inline constexpr ListOption kLoadFaces{
    "load_faces", "--load-faces", "the loaded faces",
    "the pressure and traction act on these faces of the level's boundary, each three node "
    "ids (from 0) in any order"};
inline constexpr ListOption kLoadCurve{
    "load_curve", "--load-curve", "the load curve",
    "with loads or surface loads: scales them over time by points TIME FACTOR (seconds, "
    "increasing; linear "
    "between, held before the first and after the last, or repeated after it)"};
inline constexpr NumberOption kLoadSeconds{
    "load_seconds",
    "--load-seconds",
    "--loads-seconds",
    "the loads' duration",
    "with loads or surface loads: they act for this many seconds, then let go (default: the "
    "whole run)",
    above(0),
    std::numeric_limits<double>::infinity()};
inline constexpr ListOption kGravity{
    "gravity", "--gravity", "gravity",
    "gravity X, Y, Z in m/s^2 (default 9.81 down the up axis: 0, -9.81, 0 for y)"};
inline constexpr NumberOption kFloorHeight{
    "floor_height",
    "--floor-height",
    "--floor",
    "the floor height",
    "a floor plane at this height along the up axis, with contact (drop: at the body's lowest "
    "point at rest unless given)",
    NumberRange{},
    0};
}  // namespace scenario_option

struct ScenarioParameters {
  // wobble, twist, sag: nodes in the lowest share of the height are fixed (0: none)
  double baseShare = scenario_option::kBaseShare.defaultValue;
  // wobble: peak sideways acceleration of the pushed part, and its frequency (Hz)
  double pushAcceleration = scenario_option::kPushAcceleration.defaultValue;
  double pushFrequency = scenario_option::kPushFrequency.defaultValue;
  // drop: start this share of the height above the floor
  double dropHeight = scenario_option::kDropHeight.defaultValue;
  // twist: final angle of the top (degrees) and the time to reach it (s)
  double twistDegrees = scenario_option::kTwistDegrees.defaultValue;
  double twistSeconds = scenario_option::kTwistSeconds.defaultValue;
  std::vector<int> fixedNodes;  // every scenario: also fixed (the level's node ids)
  Points3 loads;                // every scenario: a force on each node of the level
                                // (N; nodeCount rows), or empty for none
  // Every scenario: pressures and tractions on faces of the level
  // (SurfaceLoad.h), or none.
  std::vector<SurfaceLoad> surfaceLoads;
  LoadCurve loadCurve;  // scales the loads and surface loads over time (empty: by 1)
  double loadSeconds =
      std::numeric_limits<double>::infinity();  // the loads act in the
                                                // steps that start before this time, then let go
};

// `held` (sorted node ids) with the nodes of `restNodes` inside `box` (its
// faces included) added: the union, sorted, each once. Throws Error for a
// box turned inside out, and for one that holds no node (naming the
// level's extent): either would hold nothing, without a word.
std::vector<int> fixedWithNodesInBox(const std::vector<int>& held, const Points3& restNodes,
                                     const BoundingBox& box);

// The parameters that only some scenarios read (fixedNodes: every one).
enum class ScenarioParameter {
  BaseShare,
  PushAcceleration,
  PushFrequency,
  DropHeight,
  TwistDegrees,
  TwistSeconds
};

// Each number parameter of the scenarios with its option (scenario_option),
// its field and which parameter it is: what the command line, the GUI and
// Python read a scenario's numbers through.
struct ScenarioField {
  const NumberOption* option;
  double ScenarioParameters::*field;
  ScenarioParameter parameter;
};
std::array<ScenarioField, 6> scenarioFields();

// The scenarios that read `parameter`, in scenarioNames() order; and
// whether scenario `name` is one of them (the command line refuses, and the
// GUI hides, a parameter the chosen scenario would ignore).
std::vector<std::string> scenariosReading(ScenarioParameter parameter);
bool scenarioReads(std::string_view name, ScenarioParameter parameter);
// Why scenario `name` refuses `parameter`: "applies to the wobble, twist and
// sag scenarios, not to drop" (after the option's name).
std::string notReadBy(std::string_view name, ScenarioParameter parameter);

class Scenario {
 public:
  virtual ~Scenario() = default;
  explicit Scenario(const ScenarioParameters& parameters) : p_(parameters) {}
  virtual const char* name() const = 0;
  // Fixed nodes (the scenario's own and the held ones) and the initial
  // state: called once before the first step.
  void setUp(Simulation& simulation);
  // Sets the external forces (the scenario's, and the loads times the load
  // curve's factor at `time`), the surface loads' factor and the kinematic
  // targets for the step that starts at `time`.
  void beforeStep(Simulation& simulation, double time);

 protected:
  // The scenario's own part of beforeStep(): adds its forces to `forces`
  // (zero, one row per node) and sets its targets.
  virtual void drive(Simulation& simulation, double time, Points3& forces) = 0;
  // The scenario's own part of setUp(): its initial state, forces and
  // targets; returns the nodes it fixes (setUp() adds the held ones).
  virtual std::vector<int> prepare(Simulation& simulation) = 0;
  ScenarioParameters p_;

 private:
  Points3 forces_;  // beforeStep()'s, kept between steps (no allocation per step)
};

// The simulation options a scenario needs (e.g. drop adds a floor).
SimulationOptions scenarioOptions(std::string_view name, SimulationOptions options,
                                  const TetMesh& rest);

// A warning (without "warning: ") when nodes start below the simulation's
// floor (e.g. a floor set through the body): contact then throws them up,
// against any fixed base. Empty when none does or there is no floor.
std::string nodesBelowFloor(const Simulation& simulation);

// Throws Error for an unknown name, or naming the parameter whose value no
// scenario can use (e.g. a base share outside [0, 1), a twist time <= 0,
// anything not finite, a load curve without loads; loads of another level:
// setUp() checks their count, and the surface loads' nodes).
std::unique_ptr<Scenario> makeScenario(std::string_view name,
                                       const ScenarioParameters& parameters = {});
std::vector<std::string> scenarioNames();
// Whether `name` is one of scenarioNames().
bool isScenario(std::string_view name);

// The scenario a run request runs when it names none.
inline constexpr const char* kDefaultScenario = "wobble";

// The option naming the scenario (OptionSchema.h; its choices
// scenarioNames(), its default kDefaultScenario).
inline constexpr ListOption kScenarioOption{"scenario", "--scenario", "the scenario",
                                            "the loads and held nodes of the run: "};

}  // namespace tetskin
