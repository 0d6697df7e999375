// SPDX-License-Identifier: AGPL-3.0-or-later
// Simulation: a run of the corotated FEM on a dataset level through the run
// layer (SimulationSession), as `tetskin simulate` and the GUI run it, with
// the state as NumPy arrays, forces and fixed nodes from Python, and
// recording to a ParaView time series.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <set>

#include "Api.h"
#include "ArrayConversion.h"
#include "KeywordOptions.h"
#include "Objects.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/session/RunSpecJson.h"

namespace tetskin::python {
namespace {

using Object = SimulationObject;

std::shared_ptr<Object> make(const DatasetObject& dataset, int level,
                             std::optional<std::string> scenario, const py::kwargs& kwargs) {
  Keywords keywords(kwargs, "Simulation");
  const Dataset& data = *dataset.dataset;
  RunRequest request = runRequest(keywords);
  request.level = resolveLevel(data.mesh, level);
  request.datasetName = dataset.path.string();
  if (scenario) request.scenario = *scenario;
  if (!isScenario(request.scenario))
    throw Error("Simulation: scenario: unknown scenario '" + request.scenario +
                "' (known: " + listed(scenarioNames()) + ")");
  const Index nodes = data.mesh.levels[static_cast<std::size_t>(request.level)].nodeCount;
  readScenarioParameters(keywords, nodes, request);
  keywords.finish();
  const RunSpec spec = resolveRun(request, data.mesh, data.config);
  auto object = std::make_shared<Object>();
  object->dataset = dataset.dataset;
  object->spec = spec;
  {
    py::gil_scoped_release unlocked;
    object->session = std::make_unique<SimulationSession>(dataset.dataset->mesh, spec);
  }
  object->forces = Points3::Zero(nodes, 3);
  warnOfRun(*object);
  return object;
}

py::dict statsDict(const StepStats& stats, double seconds) {
  py::dict d;
  d["solver"] = toString(stats.solver);
  d["iterations"] = stats.iterations;
  d["residual"] = stats.residual;
  d["contacts"] = stats.contacts;
  d["assembly_seconds"] = stats.assemblySeconds;
  d["setup_seconds"] = stats.setupSeconds;
  d["solve_seconds"] = stats.solveSeconds;
  d["seconds"] = seconds;
  return d;
}

py::object step(Object& s, int n) {
  if (n < 0) throw Error("step: n must be >= 0");
  StepStats stats;
  for (int i = 0; i < n; ++i) {
    {
      py::gil_scoped_release unlocked;
      std::lock_guard lock(s.changing);
      stats = s.session->stepRecordingEvery(s.recordEvery, s.forcesGiven ? &s.forces : nullptr);
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C between steps
  }
  warnOfRun(s);
  if (n == 0) return py::none();
  return statsDict(stats, s.session->lastStepSeconds());
}

py::dict solveStatic(Object& s) {
  StaticStats stats;
  {
    py::gil_scoped_release unlocked;
    std::lock_guard lock(s.changing);
    stats = s.session->solveStatic();
  }
  py::dict d;
  d["converged"] = stats.converged;
  d["iterations"] = stats.iterations;
  d["linear_iterations"] = stats.linearIterations;
  d["residual"] = stats.residual;
  d["load"] = stats.load;
  d["floor"] = stats.floor;
  return d;
}

void setRows(Object& s, py::handle value, const char* name, bool positions) {
  const Points3 rows = points3(value, name);
  if (rows.rows() != s.nodeCount())
    throw Error(std::string(name) + ": expected one row per node of " + s.levelWords() + ", got " +
                std::to_string(rows.rows()));
  py::gil_scoped_release unlocked;
  std::lock_guard lock(s.changing);
  if (positions)
    s.session->simulation().setPositions(rows);
  else
    s.session->simulation().setVelocities(rows);
}

// Simulation's docstring: the scenarios and keywords as the schema has them.
const char* simulationHelp() {
  static const std::string help = [] {
    std::vector<std::string> others;
    for (const std::string& name : scenarioNames())
      if (name != kDefaultScenario) others.push_back("'" + name + "'");
    return "Simulates `level` of `dataset` (negative: from the finest). scenario: '" +
           std::string(kDefaultScenario) + "' (None: the default, as in every front end), " +
           oneOf(others) +
           " ('sag' with base_share=0: a free body). Warnings of the run (nodes starting below "
           "the floor, solves stopped at the iteration limit) come as Python UserWarnings. "
           "Keyword options as `tetskin simulate`'s, by config key (the flag, - as _): " +
           runKeywordsHelp() + ".";
  }();
  return help.c_str();
}

const char* solverHelp() {
  static const std::string help = "the solver option: " + simulation_option::kSolver.fullHelp();
  return help.c_str();
}

}  // namespace

void warnOfRun(SimulationObject& s) {
  for (const std::string& warning : s.session->takeWarnings(OptionNames::Keys))
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
}

void addSimulationApi(py::module_& m) {
  py::class_<Object, std::shared_ptr<Object>>(
      m, "Simulation",
      "A run of the corotated FEM on a dataset level, as `tetskin simulate` runs it.")
      .def(py::init(&make), py::arg("dataset"), py::arg(kLevelOption.key) = kFinestLevel,
           py::arg(kScenarioOption.key) = py::none(), simulationHelp())
      .def("step", &step, py::arg("n") = 1,
           "Takes n implicit steps (without the GIL); returns the last one's statistics "
           "(solver, iterations, residual, contacts, seconds by stage).")
      .def("solve_static", &solveStatic,
           "Moves the body to its static equilibrium under the scenario's loads, gravity, held "
           "nodes, floor and obstacles (Newton's method from the present positions; velocities "
           "become zero, time stays); returns converged, iterations, linear_iterations, "
           "residual (N, the largest force left on a free node) and load (N, the largest load "
           "on one). Raises tetskin.Error when there is no equilibrium (a free body under a "
           "net load).")
      .def_property_readonly(
          "time", [](const Object& s) { return s.session->simulation().time(); },
          "seconds simulated")
      .def_property_readonly(
          "steps", [](const Object& s) { return s.session->simulation().steps(); }, "steps taken")
      .def_property_readonly(
          "level", [](const Object& s) { return s.session->level(); }, "the simulated level")
      .def_property_readonly(
          "solver",
          [](const Object& s) { return std::string(toString(s.session->options().solver)); },
          solverHelp())
      .def_property_readonly(
          "run_spec",
          [](const Object& s) {
            return py::module_::import("json").attr("loads")(runSpecJson(s.spec));
          },
          "the run as resolved from the keywords, the dataset config and the defaults: a dict "
          "field by field, as `tetskin simulate --print-run` prints it")
      .def_property_readonly(
          "positions", [](const Object& s) { return owning(s.session->state().positions); },
          "node positions now, float64 (n, 3), the level's numbering (a copy)")
      .def_property_readonly(
          "velocities", [](const Object& s) { return owning(s.session->state().velocities); },
          "node velocities now, float64 (n, 3) (a copy)")
      .def_property_readonly(
          "fixed_nodes", [](const Object& s) { return s.session->simulation().fixedNodes(); },
          "the nodes held still (the scenario's and fix_nodes')")
      .def(
          "set_positions", [](Object& s, py::handle X) { setRows(s, X, "positions", true); },
          py::arg("positions"), "Replaces the node positions (float (n, 3)).")
      .def(
          "set_velocities", [](Object& s, py::handle V) { setRows(s, V, "velocities", false); },
          py::arg("velocities"), "Replaces the node velocities (float (n, 3)).")
      .def(
          "fix_nodes",
          [](Object& s, py::handle ids) {
            const std::vector<int> added = idList(ids, "ids", s.nodeCount(), s.levelWords());
            py::gil_scoped_release unlocked;
            std::lock_guard lock(s.changing);
            Simulation& sim = s.session->simulation();
            std::set<int> fixed(sim.fixedNodes().begin(), sim.fixedNodes().end());
            fixed.insert(added.begin(), added.end());
            sim.setFixedNodes(std::vector<int>(fixed.begin(), fixed.end()));
          },
          py::arg("ids"), "Holds these nodes (the level's ids) still, besides those held already.")
      .def(
          "apply_forces",
          [](Object& s, py::handle ids, py::handle forces) {
            const std::vector<int> nodes = idList(ids, "ids", s.nodeCount(), s.levelWords());
            const Points3 f = points3(forces, "forces");
            if (f.rows() != static_cast<Index>(nodes.size()))
              throw Error("forces: expected one row per id (" + std::to_string(nodes.size()) +
                          "), got " + std::to_string(f.rows()));
            py::gil_scoped_release unlocked;
            std::lock_guard lock(s.changing);
            s.forces.setZero();
            for (std::size_t i = 0; i < nodes.size(); ++i)
              s.forces.row(nodes[i]) += f.row(static_cast<Index>(i));
            s.forcesGiven = !nodes.empty();
          },
          py::arg("ids"), py::arg("forces"),
          "Forces (newtons, float (k, 3)) on the nodes `ids`, added to the scenario's in every "
          "step from now on; replaces the forces of an earlier call (none: empty ids).")
      .def(
          "energies",
          [](const Object& s) {
            const Energies e = s.session->simulation().energies();
            py::dict d;
            d["kinetic"] = e.kinetic;
            d["elastic"] = e.elastic;
            d["gravitational"] = e.gravitational;
            d["load"] = e.load;
            d["total"] = e.total();
            return d;
          },
          "Kinetic, elastic, gravitational, the surface loads' potential and the total energy "
          "now, joules (the potentials from the rest shape).")
      .def(
          "contact_forces",
          [](const Object& s) {
            const Simulation& sim = s.session->simulation();
            return owning(sim.contactForces(sim.state()));
          },
          "The floor's and obstacles' force on each node now (their springs and the "
          "obstacles' friction of the last step), newtons, float64 (n, 3).")
      .def(
          "von_mises",
          [](const Object& s) {
            const Simulation& sim = s.session->simulation();
            return owning(sim.frameFields(sim.state()).vonMisesStress);
          },
          "The von Mises stress per element now, pascals, float64 (m,).")
      .def(
          "stress",
          [](const Object& s) {
            const Simulation& sim = s.session->simulation();
            return owning(sim.frameFields(sim.state()).stress);
          },
          "The stress tensor per element now, pascals, float64 (m, 6): xx, yy, zz, xy, yz, xz "
          "in the world's axes (the corotated material's stress turned with the element).")
      .def(
          "surface_load_forces",
          [](const Object& s) {
            const Simulation& sim = s.session->simulation();
            return owning(sim.surfaceLoadForces(sim.state()));
          },
          "The surface loads' (pressure's and traction's) consistent force on each node now, at "
          "their present factor, newtons, float64 (n, 3).")
      .def(
          "record",
          [](Object& s, const std::filesystem::path& path, std::shared_ptr<BindingObject> surface,
             int every, int pieces) {
            for (const auto& [option, value] :
                 {std::pair{&recording_option::kEvery, every}, std::pair{&kPiecesOption, pieces}})
              if (const auto problem = option->problem(value))
                throw Error(std::string("record: ") + option->key + ": " + *problem);
            if (surface) {
              if (surface->dataset != s.dataset)
                checkBindingFits(surface->bound, s.dataset->mesh, "surface");
              if (surface->bound.binding.level != s.session->level())
                throw Error("surface: bound to level " +
                            std::to_string(surface->bound.binding.level) +
                            ", the simulation runs level " + std::to_string(s.session->level()));
            }
            py::gil_scoped_release unlocked;
            std::lock_guard lock(s.changing);
            if (surface)
              s.session->bindSurface(surface->bound.surface, surface->bound.binding,
                                     surface->bound.dataset);
            s.recordEvery = every;
            s.session->record(path, pieces);
            s.session->recordFrame();
          },
          py::arg("path"), py::arg("surface") = py::none(),
          py::arg("every") = static_cast<int>(recording_option::kEvery.defaultValue),
          py::arg("pieces") = static_cast<int>(kPiecesOption.defaultValue),
          "Records the run to `path` (.pvd, frames in PATH_frames/) as `tetskin simulate -o` "
          "does: the state now, then every `every`-th step; with `surface` (a Binding of this "
          "level), the surface deformed in each frame too, as a .pvtp in `pieces` pieces "
          "where pieces > 1 (simulate --pieces).")
      .def(
          "stop_recording",
          [](Object& s) {
            py::gil_scoped_release unlocked;
            std::lock_guard lock(s.changing);
            s.session->stopRecording();
          },
          "Ends the recording; the series stays as written.")
      .def("__repr__", [](const Object& s) {
        return "<tetskin.Simulation " + s.levelWords() + ", scenario " +
               s.session->scenario().name() +
               ", t = " + std::to_string(s.session->simulation().time()) + " s>";
      });
}

}  // namespace tetskin::python
