// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ArrayConversion.h"

#include <cmath>
#include <limits>

#include "tetskin/core/Error.h"

namespace tetskin::python {
namespace {

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d)
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// `value` as an array of shape (n, columns) (a list of rows too), else Error.
py::array rowsArray(py::handle value, const char* name, py::ssize_t columns) {
  py::array array = py::array::ensure(value);
  if (!array) {
    PyErr_Clear();
    throw Error(std::string(name) + ": expected an (n, " + std::to_string(columns) +
                ") array, got " +
                std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  }
  // An empty list is an empty array of rows.
  if (array.ndim() == 1 && array.shape(0) == 0)
    return py::array_t<double>(std::vector<py::ssize_t>{0, columns});
  if (array.ndim() != 2 || array.shape(1) != columns)
    throw Error(std::string(name) + ": expected an (n, " + std::to_string(columns) +
                ") array, got shape " + shapeText(array));
  return array;
}

char kindOf(const py::array& array) {
  return array.dtype().kind();
}

std::string dtypeName(const py::array& array) {
  return py::str(array.dtype());
}

}  // namespace

py::array_t<double, py::array::c_style> realRows(py::handle value, const char* name,
                                                 py::ssize_t columns, bool finite) {
  const py::array array = rowsArray(value, name, columns);
  const char kind = kindOf(array);
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw Error(std::string(name) + ": expected real numbers, got " + dtypeName(array));
  auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (finite) {
    const double* data = rows.data();
    for (py::ssize_t i = 0; i < rows.size(); ++i)
      if (!std::isfinite(data[i]))
        throw Error(std::string(name) + ": row " + std::to_string(i / columns) +
                    " is not finite (" + std::to_string(data[i]) + ")");
  }
  return rows;
}

Points3 points3(py::handle value, const char* name) {
  const auto rows = realRows(value, name, 3);
  return Eigen::Map<const Points3>(rows.data(), rows.shape(0), 3);
}

Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> intRows(py::handle value,
                                                                            const char* name,
                                                                            py::ssize_t columns) {
  const py::array array = rowsArray(value, name, columns);
  const char kind = kindOf(array);
  // (An empty list reads as float64: no entry to be a fraction.)
  if (kind != 'i' && kind != 'u' && array.size() > 0)
    throw Error(std::string(name) + ": expected whole numbers (an integer array), got " +
                dtypeName(array));
  const auto rows =
      py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(array);
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> result(rows.shape(0),
                                                                             columns);
  const long long* data = rows.data();
  for (py::ssize_t i = 0; i < rows.size(); ++i) {
    if (data[i] < std::numeric_limits<int>::min() || data[i] > std::numeric_limits<int>::max())
      throw Error(std::string(name) + ": row " + std::to_string(i / columns) + " holds " +
                  std::to_string(data[i]) + ", beyond any index");
    result.data()[i] = static_cast<int>(data[i]);
  }
  return result;
}

std::vector<int> idList(py::handle value, const char* name, Index bound, const std::string& what) {
  py::array array = py::array::ensure(value);
  if (!array) {
    PyErr_Clear();
    throw Error(std::string(name) + ": expected a sequence of node ids");
  }
  if (array.ndim() != 1)
    throw Error(std::string(name) + ": expected a 1-d sequence of node ids, got shape " +
                shapeText(array));
  if (array.size() > 0 && kindOf(array) != 'i' && kindOf(array) != 'u')
    throw Error(std::string(name) + ": expected whole numbers (node ids), got " + dtypeName(array));
  const auto ids = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(array);
  std::vector<int> result;
  result.reserve(static_cast<std::size_t>(ids.size()));
  for (py::ssize_t i = 0; i < ids.size(); ++i) {
    const long long id = ids.data()[i];
    if (id < 0 || id >= bound)
      throw Error(std::string(name) + ": " + std::to_string(id) + " is no node of " + what +
                  " (0.." + std::to_string(bound - 1) + ")");
    result.push_back(static_cast<int>(id));
  }
  return result;
}

}  // namespace tetskin::python
