// SPDX-License-Identifier: AGPL-3.0-or-later
// Binding, bind, load_binding and deform: a surface bound to a dataset
// level (`tetskin bind`) and deformed by control positions (`tetskin
// deform`), with the binding's arrays as NumPy views.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>

#include "Api.h"
#include "ArrayConversion.h"
#include "Objects.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/core/Error.h"
#include "tetskin/deformation/VertexNormals.h"
#include "tetskin/io/Dataset.h"

namespace tetskin::python {
namespace {

// An (n, 3) view of the first three columns of a binding's (n, 4) rows, or
// all four for embed (its vertices have four controls).
template <class Rows>
py::array controlColumns(const BindingObject& b, const Rows& rows, py::handle owner) {
  return view(rows.data(), rows.rows(), b.bound.binding.controlsPerVertex(), 4, owner);
}

std::shared_ptr<BindingObject> bindingWith(std::shared_ptr<const Dataset> dataset,
                                           BoundSurface bound) {
  auto b = std::make_shared<BindingObject>();
  b->dataset = std::move(dataset);
  b->bound = std::move(bound);
  return b;
}

// An (n, 3) float64 C-contiguous writable array for `out`, else Error.
py::array_t<double> outputRows(py::handle value, const char* name, Index rows) {
  auto array = py::array_t<double>::ensure(value);
  if (!array || !(array.flags() & py::array::c_style) || !array.writeable() || array.ndim() != 2 ||
      array.shape(0) != rows || array.shape(1) != 3)
    throw Error(std::string("out: ") + name +
                " must be a writable C-contiguous float64 array "
                "of shape (" +
                std::to_string(rows) + ", 3)");
  return array;
}

py::tuple deform(BindingObject& b, py::handle controlPositions, py::object out) {
  const auto given = realRows(controlPositions, "control_positions", 3);
  const Eigen::Map<const Points3> rows(given.data(), given.shape(0), 3);
  // Every dataset node: read where they lie; the bound level's alone: placed
  // among the others at rest.
  Points3 levelPlaced;
  if (rows.rows() != b.dataset->mesh.nodes.rows())
    levelPlaced =
        datasetPositions(b.dataset->mesh, b.bound.binding.level, rows, "control_positions");
  const ConstPoints3Ref control =
      levelPlaced.rows() > 0 ? ConstPoints3Ref(levelPlaced) : ConstPoints3Ref(rows);
  const Index n = b.bound.surface.vertexCount();
  if (!out.is_none()) {
    if (!py::isinstance<py::tuple>(out) || py::len(out) != 2)
      throw Error("out: expected a tuple (V, N) of two arrays");
    auto positions = outputRows(out[py::int_(0)], "V", n);
    auto normals = outputRows(out[py::int_(1)], "N", n);
    Eigen::Map<Points3> p(positions.mutable_data(), n, 3), q(normals.mutable_data(), n, 3);
    {
      py::gil_scoped_release unlocked;
      std::lock_guard lock(b.deforming);
      b.madeDeformer().deform(control, Points3Ref(p), Points3Ref(q));
    }
    return py::make_tuple(positions, normals);
  }
  Points3 positions, normals;
  {
    py::gil_scoped_release unlocked;
    std::lock_guard lock(b.deforming);
    b.madeDeformer().deform(control, positions, normals);
  }
  return py::make_tuple(owning(std::move(positions)), owning(std::move(normals)));
}

// bind's docstring, the methods and offsets as the schema has them.
const char* bindHelp() {
  static const std::string help =
      "Binds the surface (V, F) to a level of `dataset` (negative: from the finest), as "
      "`tetskin bind`: " +
      std::string(binding_option::kMethod.key) + " " + binding_option::kMethod.fullHelp() +
      " (default " + toString(BindingOptions{}.method) + "); " + binding_option::kOffset.key + " " +
      binding_option::kOffset.fullHelp() + " (default " + toString(BindingOptions{}.offset) +
      "; not for embed).";
  return help.c_str();
}

}  // namespace

void addBindingApi(py::module_& m) {
  py::class_<BindingObject, std::shared_ptr<BindingObject>>(
      m, "Binding",
      "A surface bound to a dataset level (bind, load_binding): per vertex its control nodes "
      "(the dataset's numbering), weights and offset.")
      .def_property_readonly(
          "control_ids",
          [](py::object self) {
            const auto& b = self.cast<BindingObject&>();
            return controlColumns(b, b.bound.binding.controlIds, self);
          },
          "int32 (n, 3) node ids per vertex, in the dataset's numbering ((n, 4) for embed)")
      .def_property_readonly(
          "weights",
          [](py::object self) {
            const auto& b = self.cast<BindingObject&>();
            return controlColumns(b, b.bound.binding.weights, self);
          },
          "float64 (n, 3) barycentric weights per vertex, each row summing to 1 ((n, 4) for embed)")
      .def_property_readonly(
          "distance",
          [](py::object self) {
            return view(self.cast<BindingObject&>().bound.binding.distance, self);
          },
          "float64 (n,): signed distance to the bound triangle's plane (embed: to the nearest "
          "element)")
      .def_property_readonly(
          "min_barycentric",
          [](py::object self) {
            return view(self.cast<BindingObject&>().bound.binding.minBarycentric, self);
          },
          "float64 (n,): the smallest weight; < 0 where the vertex projects outside its triangle")
      .def_property_readonly(
          "face_id",
          [](py::object self) {
            return view(self.cast<BindingObject&>().bound.binding.faceId, self);
          },
          "int32 (n,): the element each vertex is bound to, in the dataset's numbering")
      .def_property_readonly(
          "vertices",
          [](py::object self) {
            return view(self.cast<BindingObject&>().bound.surface.positions, self);
          },
          "float64 (n, 3): the bound surface at rest")
      .def_property_readonly(
          "triangles",
          [](py::object self) {
            return view(self.cast<BindingObject&>().bound.surface.triangles, self);
          },
          "int32 (m, 3): the bound surface's triangles")
      .def_property_readonly(
          "level", [](const BindingObject& b) { return b.bound.binding.level; },
          "the dataset level it is bound to")
      .def_property_readonly(
          "method",
          [](const BindingObject& b) { return std::string(toString(b.bound.binding.method)); },
          "'closest', 'seed' or 'embed'")
      .def_property_readonly(
          "offset",
          [](const BindingObject& b) { return std::string(toString(b.bound.binding.offset)); },
          "'normal' or 'displacement'")
      .def_property_readonly(
          "dataset_path", [](const BindingObject& b) { return b.bound.dataset; },
          "the dataset it refers to, as saved in its file")
      .def("__len__", [](const BindingObject& b) { return b.bound.surface.vertexCount(); })
      .def(
          "save",
          [](const BindingObject& b, const std::filesystem::path& path) {
            py::gil_scoped_release unlocked;
            writeBinding(path, b.bound);
          },
          py::arg("path"),
          "Writes the binding as `tetskin bind` does (.vtp: the surface at rest with the "
          "binding's arrays and the dataset it names), through a temporary file.")
      .def("__repr__", [](const BindingObject& b) {
        return "<tetskin.Binding " + std::to_string(b.bound.surface.vertexCount()) +
               " vertices on level " + std::to_string(b.bound.binding.level) + ", " +
               toString(b.bound.binding.method) + ">";
      });

  m.def(
      "bind",
      [](const DatasetObject& dataset, py::handle V, py::handle F, int level,
         const std::string& method, std::optional<std::string> offset, double tieTolerance) {
        BindingOptions options;
        options.method = fromName<BindingMethod>(method);
        if (options.method == BindingMethod::Embed && offset)
          throw Error(
              "offset: applies to the closest and seed methods, not to embed (an embedded "
              "vertex is its tetrahedron's barycentric combination, with no offset)");
        options.offset = fromName<OffsetMode>(offset.value_or(toString(OffsetMode::Normal)));
        if (!(tieTolerance >= 0 && tieTolerance <= 1))
          throw Error("tie_tolerance: must lie in [0, 1]");
        options.tieTolerance = tieTolerance;
        BoundSurface bound;
        bound.surface.positions = points3(V, "V");
        bound.surface.triangles = intRows(F, "F", 3);
        validateSurface(bound.surface, "(V, F)");
        const int resolved = resolveLevel(dataset.dataset->mesh, level);
        {
          py::gil_scoped_release unlocked;
          bound.binding = bindSurface(bound.surface, dataset.dataset->mesh, resolved, options);
          bound.surface.normals = vertexNormals(bound.surface.positions, bound.surface.triangles);
        }
        bound.dataset = dataset.path.generic_string();
        return bindingWith(dataset.dataset, std::move(bound));
      },
      py::arg("dataset"), py::arg("V"), py::arg("F"), py::arg(kLevelOption.key) = kFinestLevel,
      py::arg(binding_option::kMethod.key) = std::string(toString(BindingOptions{}.method)),
      py::arg(binding_option::kOffset.key) = py::none(), py::arg("tie_tolerance") = 1e-6,
      bindHelp());

  m.def(
      "load_binding",
      [](const std::filesystem::path& path, std::shared_ptr<DatasetObject> dataset) {
        BoundSurface bound;
        std::shared_ptr<const Dataset> data;
        {
          py::gil_scoped_release unlocked;
          if (!dataset) {
            bound = readBinding(path);
            if (bound.dataset.empty())
              throw Error(path.string() + ": names no dataset: pass dataset=");
            data = std::make_shared<const Dataset>(loadDataset(bound.dataset));
            checkBindingFits(bound, data->mesh, path.string());
          } else {
            data = dataset->dataset;
            bound = readBinding(path, data->mesh);
            bound.dataset = dataset->path.generic_string();
          }
        }
        return bindingWith(std::move(data), std::move(bound));
      },
      py::arg("path"), py::arg("dataset") = py::none(),
      "The binding in `path` (a .vtp from `tetskin bind` or Binding.save), checked against "
      "`dataset`, by default the dataset the file names.");

  m.def("deform", &deform, py::arg("binding"), py::arg("control_positions"),
        py::arg("out") = py::none(),
        "The bound surface deformed by `control_positions` (float (N, 3): every dataset node, "
        "or the bound level's alone), as `tetskin deform`: (V, N), the deformed vertices and "
        "their unit normals, float64 (n, 3). out=(V, N): write into these arrays instead "
        "(C-contiguous float64), allocating nothing.");
}

}  // namespace tetskin::python
