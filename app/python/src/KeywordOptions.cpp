// SPDX-License-Identifier: AGPL-3.0-or-later
#include "KeywordOptions.h"

#include <cmath>
#include <vector>

#include "ArrayConversion.h"
#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/Error.h"
#include "tetskin/core/LoadCurve.h"
#include "tetskin/core/NumberText.h"

namespace tetskin::python {

// (A copy: reading a keyword removes it, and the caller may ask what it was given.)
Keywords::Keywords(const py::kwargs& kwargs, std::string call)
    : given_(kwargs.attr("copy")()), call_(std::move(call)) {}

std::optional<py::object> Keywords::take(const char* key, bool listedAsKnown) {
  if (listedAsKnown) known_.insert(key);
  if (!given_.contains(key)) return std::nullopt;
  py::object value = given_[key];
  PyDict_DelItemString(given_.ptr(), key);
  return value;
}

std::optional<py::object> Keywords::orOtherName(std::optional<py::object> value, std::string& name,
                                                const std::string& other, bool old) {
  std::optional<py::object> byOther = take(other.c_str(), !old);
  if (!byOther) return value;
  if (value) throw Error(call_ + ": " + name + " and " + other + " are the same option: give one");
  if (old && PyErr_WarnEx(PyExc_DeprecationWarning, deprecatedName(other, name).c_str(), 1) != 0)
    throw py::error_already_set();
  name = other;
  return byOther;
}

std::optional<double> Keywords::number(const NumberOption& option) {
  std::string name = option.key;
  std::optional<py::object> value = take(option.key);
  // The flag's name where it is not the key (fur_length for the fur
  // section's length), and the old flag's, with a warning.
  for (const std::string& other : {keywordOf(option.flag), keywordOf(option.oldFlag)})
    if (!other.empty() && other != option.key)
      value = orOtherName(value, name, other, other == keywordOf(option.oldFlag));
  if (!value) return std::nullopt;
  if (py::isinstance<py::bool_>(*value) ||
      !(py::isinstance<py::float_>(*value) || py::isinstance<py::int_>(*value) ||
        py::hasattr(*value, "__float__")))
    throw Error(call_ + ": " + name + ": expected a number, got " +
                std::string(py::str(py::type::handle_of(*value).attr("__name__"))));
  const double number = value->cast<double>();
  if (const std::optional<std::string> problem = option.problem(number))
    throw Error(call_ + ": " + name + ": " + *problem);
  return number;
}

std::optional<int> Keywords::count(const NumberOption& option) {
  const std::optional<double> value = number(option);
  if (!value) return std::nullopt;
  if (*value != std::floor(*value) || std::abs(*value) > 1e9)
    throw Error(call_ + ": " + option.key + ": expected a whole number, got " +
                formatNumber(*value));
  return static_cast<int>(*value);
}

void Keywords::finish() const {
  if (given_.empty()) return;
  const std::string unknown = py::str(given_.begin()->first);
  std::vector<std::string> known(known_.begin(), known_.end());
  throw Error(call_ + ": unknown option '" + unknown + "' (known: " + listed(known) + ")");
}

namespace {

// A keyword's (2, 3) corners, min and max.
BoundingBox boxOf(Keywords& k, const py::object& value, const ListOption& option) {
  const Points3 corners = points3(value, option.key);
  if (corners.rows() != 2)
    throw Error(k.call() + ": " + option.key + ": expected 2 corners (min, max), got " +
                std::to_string(corners.rows()));
  return BoundingBox{corners.row(0).transpose(), corners.row(1).transpose()};
}

// A keyword's three numbers, x, y, z.
Eigen::Vector3d vectorOf(Keywords& k, const py::object& value, const ListOption& option) {
  const py::array given = py::array::ensure(value);
  if (!given) PyErr_Clear();
  if (!given || given.size() != 3)
    throw Error(k.call() + ": " + option.key + ": expected 3 numbers (x, y, z)");
  return points3(given.attr("reshape")(1, 3), option.key).row(0).transpose();
}

}  // namespace

RunRequest runRequest(Keywords& k) {
  RunRequest r;
  applyRunKeywords(k, r);
  return r;
}

void applyRunKeywords(Keywords& k, RunRequest& r) {
  r.names = OptionNames::Keys;
  for (const MaterialField& field : materialFields())
    if (const auto value = k.number(*field.option)) r.material.set(*field.option, *value);
  using namespace simulation_option;
  SimulationOptions& o = r.settings;
  if (const auto v = k.number(kTimeStep)) o.timeStep = *v;
  if (const auto v = k.number(kTolerance)) o.tolerance = *v;
  if (const auto v = k.count(kGuessSolutions)) o.guessSolutions = *v;
  if (const auto v = k.count(kCoarseReuse)) o.coarseReuse = *v;
  if (const auto v = k.count(kMaxIterations)) o.maxIterations = *v;
  if (const auto v = k.number(kFriction)) o.friction = *v;
  if (const auto v = k.number(kFloorStiffness)) o.floorStiffness = *v;
  if (const auto v = k.choice(kSolver)) o.solver = *v;
  if (const auto v = k.choice(kTangent)) o.tangent = *v;
  if (const auto v = k.choice(kCoarseOperators)) o.coarseOperators = *v;
  if (const auto v = k.choice(kCoarseLevels)) o.coarseLevels = *v;
  if (const auto up = k.choice(kUpOption)) r.up = up;
  using scenario_option::kGravity;
  if (const auto gravity = k.take(kGravity.key)) r.gravity = vectorOf(k, *gravity, kGravity);
  if (const auto height = k.number(scenario_option::kFloorHeight)) r.floorHeight = *height;
}

void readScenarioParameters(Keywords& k, Index levelNodes, RunRequest& r) {
  ScenarioParameters& p = r.parameters;
  for (const ScenarioField& f : scenarioFields())
    if (const auto value = k.number(*f.option)) {
      if (!scenarioReads(r.scenario, f.parameter))
        throw Error(k.call() + ": " + f.option->key + ": " + notReadBy(r.scenario, f.parameter));
      p.*f.field = *value;
    }
  const std::string level = "the level (" + std::to_string(levelNodes) + " nodes)";
  using namespace scenario_option;
  const auto named = [&k](const ListOption& option) { return k.call() + ": " + option.key; };
  // (held_nodes: the old name, as --fixed-nodes named them on the command
  // line all along; read with a warning.)
  std::string fixedName = kFixedNodes.key;
  const std::optional<py::object> fixed =
      k.orOtherName(k.take(kFixedNodes.key), fixedName, "held_nodes", true);
  if (fixed) p.fixedNodes = idList(*fixed, kFixedNodes.key, levelNodes, level);
  if (const auto box = k.take(kFixedBox.key)) r.fixedBox = boxOf(k, *box, kFixedBox);
  if (const auto loads = k.take(kLoads.key)) {
    p.loads = points3(*loads, kLoads.key);
    if (p.loads.rows() != levelNodes)
      throw Error(named(kLoads) + ": expected one row per node of " + level + ", got " +
                  std::to_string(p.loads.rows()));
  }
  // One surface load: pressure and traction on the faces of load_box or
  // load_faces (a face-set file's path, or an (n, 3) array of node ids).
  SurfaceLoadRequest surface;
  const std::optional<double> pressure = k.number(kPressure);
  const std::optional<py::object> traction = k.take(kTraction.key);
  const std::optional<py::object> loadBox = k.take(kLoadBox.key);
  const std::optional<py::object> loadFaces = k.take(kLoadFaces.key);
  if ((pressure || traction) != (loadBox || loadFaces))
    throw Error(k.call() + ": " +
                (pressure || traction
                     ? std::string(kPressure.key) + " and " + kTraction.key + " need " +
                           kLoadBox.key + " or " + kLoadFaces.key + ": the faces they act on"
                     : std::string(loadBox ? kLoadBox.key : kLoadFaces.key) +
                           ": selects the faces of a pressure or traction, and neither is given"));
  if (loadBox && loadFaces)
    throw Error(k.call() + ": " + kLoadBox.key + " and " + kLoadFaces.key +
                ": give the loaded faces one way");
  if (pressure || traction) {
    surface.name = named(loadBox ? kLoadBox : kLoadFaces);
    surface.pressure = pressure.value_or(0.0);
    if (traction) surface.traction = vectorOf(k, *traction, kTraction);
    if (loadBox) {
      surface.box = boxOf(k, *loadBox, kLoadBox);
    } else if (py::isinstance<py::str>(*loadFaces) ||
               py::isinstance(*loadFaces, py::module_::import("pathlib").attr("PurePath"))) {
      surface.faceFile = py::str(*loadFaces).cast<std::string>();
    } else {
      surface.faceNodes = intRows(*loadFaces, kLoadFaces.key, 3);
    }
    r.surfaceLoads.push_back(std::move(surface));
  }
  for (const char* key : {kLoadSeconds.key, kLoadCurve.key})
    if (k.given(key) && p.loads.rows() == 0 && r.surfaceLoads.empty())
      throw Error(k.call() + ": " + key + ": applies with " + kLoads.key + " or a surface load");
  if (const auto seconds = k.number(kLoadSeconds)) p.loadSeconds = *seconds;
  if (const auto curve = k.take(kLoadCurve.key)) {
    // (Finite or not, each point is LoadCurve's to check, naming it.)
    const auto rows = realRows(*curve, kLoadCurve.key, 2, /*finite=*/false).unchecked<2>();
    std::vector<LoadCurve::Point> points;
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) points.push_back({rows(i, 0), rows(i, 1)});
    try {
      p.loadCurve = LoadCurve(std::move(points));
    } catch (const Error& e) {
      throw Error(named(kLoadCurve) + ": " + e.what());
    }
  }
}

void readBuildOptions(Keywords& k, BuildOptions& o) {
  const char* qualitiesKey = build_option::kQualities.key;
  if (const auto qualities = k.take(qualitiesKey)) {
    o.qualities.clear();
    for (const py::handle q : *qualities) {
      const double value = q.cast<double>();
      if (!(value > 1.0))
        throw Error(k.call() + ": " + qualitiesKey + ": each must be > 1.0, got " +
                    formatNumber(value));
      o.qualities.push_back(value);
    }
    if (o.qualities.empty()) throw Error(k.call() + ": " + qualitiesKey + ": give at least one");
  }
  if (const auto v = k.take("size_to_targets")) o.sizeToTargets = v->cast<bool>();
  if (const auto v = k.take("accept_unfaithful")) o.acceptUnfaithful = v->cast<bool>();
  if (const auto v = k.count(build_option::kJobs)) o.jobs = *v;
  if (const auto v = k.number(build_option::kTimeout)) o.timeoutSeconds = *v;
  if (const auto v = k.choice(wrap_option::kMode)) o.wrap.mode = *v;
  if (const auto v = k.number(wrap_option::kAlpha)) o.wrap.alpha = *v;
  if (const auto v = k.number(wrap_option::kOffset)) o.wrap.offset = *v;
  if (const auto v = k.choice(kUpOption)) o.up = *v;
}

namespace {
// "solver ('auto', 'cg' or 'multigrid')"
template <SchemaEnum E>
std::string withNames(const EnumOption<E>& option) {
  std::vector<std::string> names;
  for (const std::string& name : namesOf<E>()) names.push_back("'" + name + "'");
  return std::string(option.key) + " (" + oneOf(names) + ")";
}
}  // namespace

std::string runKeywordsHelp() {
  std::vector<std::string> material, scenario;
  for (const MaterialField& field : materialFields()) material.emplace_back(field.option->key);
  for (const ScenarioField& field : scenarioFields()) scenario.emplace_back(field.option->key);
  using namespace simulation_option;
  using namespace scenario_option;
  const std::vector<std::string> keys = {
      "the material (" + listed(material) + "; default the dataset config's)",
      kTimeStep.key,
      withNames(kSolver),
      kTolerance.key,
      withNames(kTangent),
      withNames(kCoarseOperators),
      withNames(kCoarseLevels),
      kCoarseReuse.key,
      kGuessSolutions.key,
      kMaxIterations.key,
      kFriction.key,
      kFloorStiffness.key,
      withNames(kUpOption),
      std::string(kGravity.key) + " (3 numbers)",
      kFloorHeight.key,
      "the scenario's numbers (" + listed(scenario) + ")",
      kFixedNodes.key,
      std::string(kFixedBox.key) + " ((2, 3): min and max corners)",
      std::string(kLoads.key) + " ((n, 3) newtons on the level's nodes)",
      kLoadSeconds.key,
      std::string(kLoadCurve.key) + " ((k, 2): time in s, factor)"};
  return listed(keys);
}

}  // namespace tetskin::python
