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

}  // namespace

void addScenarioOptions(CLI::App& cmd, ScenarioArgs& a) {
  cmd.add_option("--scenario", a.name, oneOf(scenarioNames()))
      ->capture_default_str()
      ->check(CLI::IsMember(scenarioNames()));
  ScenarioParameters& p = a.parameters;
  for (const ScenarioField& f : scenarioFields())
    addNumberOption(cmd, *f.option, p.*f.field)->group(kGroup);
  cmd.add_option("--fixed-nodes", a.fixedNodes,
                 "also hold these nodes still: a text file of node numbers of the level, from 0 "
                 "(the point ids of its .vtu), separated by spaces or lines, # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  cmd.add_option("--fixed-box", a.fixedBox,
                 "also hold still the nodes of the level inside this box: XMIN,YMIN,ZMIN,XMAX,YMAX,"
                 "ZMAX in the dataset's coordinates, faces included (a beam's end, say)")
      ->expected(6)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  cmd.add_option("--loads", a.loads,
                 "forces on nodes of the level: a text file of lines NODE FX FY FZ "
                 "(newtons), # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  cmd.add_option("--load-curve", a.loadCurve,
                 "with --loads: scale them over time by a text file of lines TIME FACTOR "
                 "(seconds, increasing; linear between, held before the first and after the "
                 "last, or repeated after it with a last line 'repeat'), # comments")
      ->check(CLI::ExistingFile)
      ->group(kGroup);
  cmd.add_option("--loads-seconds", p.loadSeconds,
                 "with --loads: they act for this many seconds, then let go (default: the whole "
                 "run)")
      ->check(positiveNumber())
      ->group(kGroup);
  cmd.add_option("--gravity", a.gravity,
                 "gravity X,Y,Z in m/s^2 (default 9.81 down the up axis: 0,-9.81,0 for y)")
      ->expected(3)
      ->delimiter(',')
      ->check(finiteNumber())
      ->group(kGroup);
  cmd.add_option("--floor", a.floor,
                 "a floor plane at this height along the up axis, with contact (drop: at the "
                 "body's lowest point at rest unless given)")
      ->check(finiteNumber())
      ->group(kGroup);
  // (Not a scenario option: the camera presets follow it too.)
  cmd.add_option("--up", a.up,
                 "the axis that points up: x, y or z (default: the dataset config's up, else y); "
                 "the scenarios, the floor, the default gravity and the camera follow it")
      ->check(CLI::IsMember(namesOf<UpAxis>()));
}

UpAxis upAxisOf(const ScenarioArgs& a, const DatasetConfig& config) {
  return a.up.empty() ? config.up : fromName<UpAxis>(a.up);
}

std::optional<std::string> givenScenarioOption(const CLI::App& cmd) {
  if (cmd.count("--scenario") > 0) return "--scenario";
  return givenOptionOf(cmd, kGroup);
}

void fillScenario(const CLI::App& cmd, const ScenarioArgs& a, Index nodeCount,
                  RunRequest& request) {
  for (const ScenarioField& f : scenarioFields())
    if (const auto given = givenName(cmd, *f.option); given && !scenarioReads(a.name, f.parameter))
      throw Error(*given + ": " + notReadBy(a.name, f.parameter));
  for (const char* option : {"--load-curve", "--loads-seconds"})
    if (cmd.count(option) > 0 && a.loads.empty())
      throw Error(std::string(option) + ": applies with --loads, which is not given");
  // (Each number was checked as it was parsed; makeScenario() checks the
  // whole set again for its other callers.)
  request.scenario = a.name;
  ScenarioParameters& p = request.parameters;
  p = a.parameters;
  if (!a.fixedNodes.empty()) p.fixedNodes = readNodeList(a.fixedNodes, nodeCount);
  if (a.fixedBox.size() == 6) {
    BoundingBox box;
    box.min = {a.fixedBox[0], a.fixedBox[1], a.fixedBox[2]};
    box.max = {a.fixedBox[3], a.fixedBox[4], a.fixedBox[5]};
    request.fixedBox = box;
  }
  if (!a.loads.empty()) p.loads = readNodeForces(a.loads, nodeCount);
  if (!a.loadCurve.empty()) p.loadCurve = readLoadCurve(a.loadCurve);
  if (a.gravity.size() == 3)
    request.gravity = Eigen::Vector3d(a.gravity[0], a.gravity[1], a.gravity[2]);
  request.floorHeight = a.floor;
  if (!a.up.empty()) request.up = fromName<UpAxis>(a.up);
}

}  // namespace tetskin::cli
