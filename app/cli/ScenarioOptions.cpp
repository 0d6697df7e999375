// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ScenarioOptions.h"

#include <algorithm>
#include <iterator>
#include <utility>

#include "OptionChecks.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/LoadCurveFile.h"
#include "tetskin/io/NodeList.h"

namespace tetskin::cli {
namespace {

constexpr const char* kGroup = "Scenario";

// A box flag's six numbers, XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX.
BoundingBox boxOf(const std::vector<double>& n) {
  return BoundingBox{{n[0], n[1], n[2]}, {n[3], n[4], n[5]}};
}

}  // namespace

void addScenarioOptions(CLI::App& cmd, ScenarioArgs& a) {
  cmd.add_option(kScenarioOption.flag, a.name, kScenarioOption.help + oneOf(scenarioNames()))
      ->capture_default_str()
      ->check(CLI::IsMember(scenarioNames()));
  ScenarioParameters& p = a.parameters;
  for (const ScenarioField& f : scenarioFields())
    addNumberOption(cmd, *f.option, p.*f.field)->group(kGroup);
  // The schema's names and meaning (scenario_option), and the form each
  // takes here.
  using namespace scenario_option;
  cmd.add_option(kFixedNodes.flag, a.fixedNodes,
                 std::string(kFixedNodes.help) +
                     ": a text file of node numbers separated by spaces or lines, # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  cmd.add_option(kFixedBox.flag, a.fixedBox,
                 std::string(kFixedBox.help) + ": XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX")
      ->expected(6)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  cmd.add_option(kLoads.flag, a.loads,
                 std::string(kLoads.help) + ": a text file of lines NODE FX FY FZ, # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  addFlagOf(cmd, kPressure, a.pressure, kPressure.help, finiteNumber())->group(kGroup);
  cmd.add_option(kTraction.flag, a.traction, std::string(kTraction.help) + ": X,Y,Z")
      ->expected(3)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  cmd.add_option(kLoadBox.flag, a.loadBox,
                 std::string(kLoadBox.help) + ": XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX")
      ->expected(6)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  cmd.add_option(kLoadFaces.flag, a.loadFaces,
                 std::string(kLoadFaces.help) + ": a text file of lines A B C, # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  cmd.add_option(kLoadCurve.flag, a.loadCurve,
                 std::string(kLoadCurve.help) +
                     ": a text file of lines TIME FACTOR, and a last line 'repeat' to repeat it, "
                     "# comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  addFlagOf(cmd, kLoadSeconds, p.loadSeconds, kLoadSeconds.help, positiveNumber())->group(kGroup);
  cmd.add_option(kGravity.flag, a.gravity, std::string(kGravity.help) + ": X,Y,Z")
      ->expected(3)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  addFlagOf(cmd, kFloorHeight, a.floor, kFloorHeight.help, finiteNumber())->group(kGroup);
  // (Not a scenario option: the camera presets follow it too.)
  // (No default shown: the dataset config's.)
  cmd.add_option(kUpOption.flag, a.up,
                 kUpOption.fullHelp() +
                     " (default: the dataset config's up, else y); the scenarios, the floor, the "
                     "default gravity and the camera follow it")
      ->check(CLI::IsMember(namesOf<UpAxis>()));
}

UpAxis upAxisOf(const ScenarioArgs& a, const DatasetConfig& config) {
  return a.up.empty() ? config.up : fromName<UpAxis>(a.up);
}

std::optional<std::string> givenScenarioOption(const CLI::App& cmd) {
  if (cmd.count(kScenarioOption.flag) > 0) return kScenarioOption.flag;
  return givenOptionOf(cmd, kGroup);
}

void fillScenario(const CLI::App& cmd, const ScenarioArgs& a, Index nodeCount,
                  RunRequest& request) {
  // Only what was given: the request may hold a scene's values already.
  if (cmd.count(kScenarioOption.flag) > 0) request.scenario = a.name;
  for (const ScenarioField& f : scenarioFields())
    if (const auto given = givenName(cmd, *f.option);
        given && !scenarioReads(request.scenario, f.parameter))
      throw Error(*given + ": " + notReadBy(request.scenario, f.parameter));
  std::optional<std::string> withLoads = givenName(cmd, scenario_option::kLoadSeconds);
  if (cmd.count(scenario_option::kLoadCurve.flag) > 0) withLoads = scenario_option::kLoadCurve.flag;
  const bool surfaceLoad = a.pressure || !a.traction.empty();
  if (withLoads && a.loads.empty() && request.parameters.loads.size() == 0 && !surfaceLoad &&
      request.surfaceLoads.empty() && request.parameters.surfaceLoads.empty())
    throw Error(*withLoads +
                ": applies with --loads or a surface load (--pressure, "
                "--traction), and none is given");
  using scenario_option::kLoadBox, scenario_option::kLoadFaces;
  const bool selected = !a.loadBox.empty() || !a.loadFaces.empty();
  if (surfaceLoad != selected)
    throw Error(surfaceLoad
                    ? std::string("--pressure and --traction need the faces they act on: ") +
                          kLoadBox.flag + " or " + kLoadFaces.flag
                    : std::string(!a.loadBox.empty() ? kLoadBox.flag : kLoadFaces.flag) +
                          ": selects the faces of --pressure or --traction, and neither "
                          "is given");
  if (!a.loadBox.empty() && !a.loadFaces.empty())
    throw Error(std::string(kLoadBox.flag) + " and " + kLoadFaces.flag +
                ": give the loaded faces one way");
  // (Each number was checked as it was parsed; makeScenario() checks the
  // whole set again for its other callers.)
  ScenarioParameters& p = request.parameters;
  for (const ScenarioField& f : scenarioFields())
    if (givenName(cmd, *f.option)) p.*f.field = a.parameters.*f.field;
  if (givenName(cmd, scenario_option::kLoadSeconds)) p.loadSeconds = a.parameters.loadSeconds;
  if (!a.fixedNodes.empty()) p.fixedNodes = readNodeList(a.fixedNodes, nodeCount);
  if (a.fixedBox.size() == 6) request.fixedBox = boxOf(a.fixedBox);
  if (!a.loads.empty()) p.loads = readNodeForces(a.loads, nodeCount);
  if (surfaceLoad) {
    SurfaceLoadRequest& load = request.surfaceLoads.emplace_back();
    load.name = !a.loadBox.empty() ? kLoadBox.flag : kLoadFaces.flag;
    load.pressure = a.pressure.value_or(0.0);
    if (!a.traction.empty()) load.traction = {a.traction[0], a.traction[1], a.traction[2]};
    if (!a.loadBox.empty()) load.box = boxOf(a.loadBox);
    load.faceFile = a.loadFaces;
  }
  if (!a.loadCurve.empty()) p.loadCurve = readLoadCurve(a.loadCurve);
  if (a.gravity.size() == 3)
    request.gravity = Eigen::Vector3d(a.gravity[0], a.gravity[1], a.gravity[2]);
  if (a.floor) request.floorHeight = a.floor;
  if (!a.up.empty()) request.up = fromName<UpAxis>(a.up);
}

}  // namespace tetskin::cli
