// SPDX-License-Identifier: AGPL-3.0-or-later
// Dataset, Level, load_dataset and build: datasets as `tetskin build` makes
// them and every form `tetskin` reads, their levels as NumPy views.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <thread>

#include "Api.h"
#include "ArrayConversion.h"
#include "KeywordOptions.h"
#include "Objects.h"
#include "tetskin/binding/BoundaryFaces.h"
#include "tetskin/meshing/DatasetBuild.h"
#include "tetskin/meshing/IsolatedJobs.h"

namespace tetskin::python {
namespace {

std::shared_ptr<DatasetObject> load(const std::filesystem::path& path) {
  auto object = std::make_shared<DatasetObject>();
  {
    py::gil_scoped_release unlocked;
    object->dataset = std::make_shared<const Dataset>(loadDataset(path));
  }
  object->path = path;
  return object;
}

std::shared_ptr<LevelObject> levelOf(const DatasetObject& d, int k) {
  auto level = std::make_shared<LevelObject>();
  level->dataset = d.dataset;
  level->index = resolveLevel(d.dataset->mesh, k);
  level->mesh = extractLevel(d.dataset->mesh, level->index);
  level->boundaryFaces = boundaryFaces(level->mesh).faces;
  return level;
}

// A progress callback (stage, done, total) and Ctrl-C for a build, which
// runs without the GIL: each call takes it back for the moment it needs.
BuildEvents buildEvents(const py::object& progress, bool& interrupted) {
  BuildEvents events;
  if (!progress.is_none())
    events.progress = [progress](const std::string& stage, std::size_t done, std::size_t total) {
      py::gil_scoped_acquire locked;
      progress(stage, done, total);
    };
  events.cancelled = [&interrupted] {
    py::gil_scoped_acquire locked;
    if (PyErr_CheckSignals() != 0) interrupted = true;  // (KeyboardInterrupt is now set)
    return interrupted;
  };
  return events;
}

std::vector<std::filesystem::path> inputPaths(const py::handle inputs) {
  if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__"))
    return {inputs.cast<std::filesystem::path>()};
  return inputs.cast<std::vector<std::filesystem::path>>();
}

// build's docstring, its keywords' names as the schema has them.
const char* buildHelp() {
  static const std::string help =
      "Model generation, as `tetskin build`: repairs the input surfaces (a path or a list of "
      "levels of detail of one object), tetrahedralizes them, chooses the levels and writes "
      "OUTPUT.json, .node and .ele; returns the Dataset. mesher: " +
      build_option::kMesher.fullHelp() +
      ". Keyword options as the command's: " + build_option::kQualities.key +
      ", size_to_targets, accept_unfaithful (write levels beyond their fidelity bound), " +
      build_option::kJobs.key + " (default: every core), " + build_option::kTimeout.key + ", " +
      wrap_option::kMode.key + " (" + oneOf(namesOf<WrapMode>()) + "), " + wrap_option::kAlpha.key +
      ", " + wrap_option::kOffset.key + ", " + kUpOption.key + " (" + oneOf(namesOf<UpAxis>()) +
      "). progress(stage, done, total) is called as it goes; Ctrl-C stops it.";
  return help.c_str();
}

}  // namespace

void addDatasetApi(py::module_& m) {
  py::class_<LevelObject, std::shared_ptr<LevelObject>>(
      m, "Level", "One level of a dataset, numbered on its own (node ids from 0).")
      .def_readonly("index", &LevelObject::index, "the level's number, 0 the coarsest")
      .def_property_readonly(
          "nodes", [](py::object self) { return view(self.cast<LevelObject&>().mesh.nodes, self); },
          "node positions at rest, float64 (n, 3), read-only")
      .def_property_readonly(
          "elements",
          [](py::object self) { return view(self.cast<LevelObject&>().mesh.elements, self); },
          "tetrahedra, int32 (m, 4) node ids of this level, positively oriented, read-only")
      .def_property_readonly(
          "boundary_faces",
          [](py::object self) { return view(self.cast<LevelObject&>().boundaryFaces, self); },
          "the boundary triangles, int32 (k, 3) node ids, counter-clockwise seen from outside")
      .def_property_readonly(
          "volume", [](const LevelObject& l) { return meshVolume(l.mesh); }, "the level's volume")
      .def_property_readonly(
          "first_node",
          [](const LevelObject& l) {
            return l.dataset->mesh.levels[static_cast<std::size_t>(l.index)].firstNode;
          },
          "the dataset's number of this level's node 0 (bindings number nodes as the dataset)")
      .def_property_readonly(
          "fidelity",
          [](const LevelObject& l) -> py::object {
            const std::optional<LevelFidelity>& f =
                l.dataset->config.levels[static_cast<std::size_t>(l.index)].fidelity;
            if (!f) return py::none();
            py::dict d;
            d["input_to_level_mean"] = f->inputToLevelMean;
            d["input_to_level_max"] = f->inputToLevelMax;
            d["level_to_input_mean"] = f->levelToInputMean;
            d["level_to_input_max"] = f->levelToInputMax;
            d["element_size"] = f->elementSize;
            d["diagonal"] = f->diagonal;
            d["bound_mean"] = f->boundMean;
            d["bound_max"] = f->boundMax;
            d["faithful"] = f->faithful;
            return d;
          },
          "how far the level's boundary lies from the input it was built from (build), in the "
          "input's units: a dict of input_to_level_mean/max, level_to_input_mean/max, "
          "element_size, diagonal, bound_mean/max and faithful; None for datasets without it")
      .def("__repr__", [](const LevelObject& l) {
        return "<tetskin.Level " + std::to_string(l.index) + ": " +
               std::to_string(l.mesh.nodeCount()) + " nodes, " +
               std::to_string(l.mesh.elementCount()) + " tetrahedra>";
      });

  py::class_<DatasetObject, std::shared_ptr<DatasetObject>>(
      m, "Dataset", "A multi-level tetrahedral dataset (load_dataset, build).")
      .def_property_readonly(
          "levels", [](const DatasetObject& d) { return d.dataset->mesh.levelCount(); },
          "the number of levels")
      .def("level", &levelOf, py::arg("k") = -1,
           "Level k, 0 the coarsest; negative k counts from the finest (-1).")
      .def_property_readonly(
          "path", [](const DatasetObject& d) { return d.path; }, "the file it was loaded from")
      .def_property_readonly(
          "up", [](const DatasetObject& d) { return std::string(toString(d.dataset->config.up)); },
          "the axis that points up: 'x', 'y' or 'z'")
      .def_property_readonly(
          "nodes",
          [](py::object self) {
            return view(self.cast<DatasetObject&>().dataset->mesh.nodes, self);
          },
          "every level's nodes, coarsest first, float64 (N, 3), read-only (binding numbering)")
      .def("__len__", [](const DatasetObject& d) { return d.dataset->mesh.levelCount(); })
      .def("__repr__", [](const DatasetObject& d) {
        return "<tetskin.Dataset " + d.path.string() + ": " +
               std::to_string(d.dataset->mesh.levelCount()) + " levels>";
      });

  m.def("load_dataset", &load, py::arg("path"),
        "The dataset at `path`: a config (.json) from build, or a tetrahedral mesh made "
        "elsewhere (.node/.ele, Gmsh .msh, MEDIT .mesh) as a one-level dataset.");

  m.def(
      "build",
      [](py::handle inputs, const std::filesystem::path& output, int levels, Index minElements,
         Index maxElements, bool decimate, const std::string& mesher, py::object progress,
         py::kwargs kwargs) {
        Keywords keywords(kwargs, "build");
        BuildOptions options;
        options.levels = levels;
        options.minElements = minElements;
        options.maxElements = maxElements;
        options.decimate = decimate;
        options.mesher = fromName<MesherKind>(mesher);
        // (As `tetskin build`: the mesher runs on every core.)
        options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        readBuildOptions(keywords, options);
        keywords.finish();
        using namespace build_option;
        for (const auto& [option, value] :
             {std::pair{&kLevels, static_cast<double>(levels)},
              std::pair{&kMinElements, static_cast<double>(minElements)},
              std::pair{&kMaxElements, static_cast<double>(maxElements)}})
          if (const auto problem = option->problem(value))
            throw Error(std::string("build: ") + option->key + ": " + *problem);
        const std::vector<std::filesystem::path> paths = inputPaths(inputs);
        bool interrupted = false;
        const BuildEvents events = buildEvents(progress, interrupted);
        std::filesystem::path config;
        try {
          py::gil_scoped_release unlocked;
          config = buildDatasetFiles(paths, output, options, events).config;
        } catch (const Cancelled&) {
          if (interrupted) throw py::error_already_set();
          throw;
        }
        return load(config);
      },
      py::arg("inputs"), py::arg("output"),
      py::arg("levels") = static_cast<int>(build_option::kLevels.defaultValue),
      py::arg("min_elements") = static_cast<Index>(build_option::kMinElements.defaultValue),
      py::arg("max_elements") = static_cast<Index>(build_option::kMaxElements.defaultValue),
      py::arg("decimate") = false,
      py::arg(build_option::kMesher.key) = std::string(toString(BuildOptions{}.mesher)),
      py::arg("progress") = py::none(), buildHelp());
}

}  // namespace tetskin::python
