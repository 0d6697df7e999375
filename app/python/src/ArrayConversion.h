// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NumPy arrays to and from the libraries' Eigen matrices: the only place the
// Python module converts data. Arrays given are checked for shape and kind
// and named in the error ("V: expected an (n, 3) array, got shape (4, 2)");
// C-contiguous float64 arrays are read where they lie. Arrays returned are
// views of the memory that holds them (an object's, kept alive by the view),
// or own a matrix moved into them: never a copy made for the conversion.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "tetskin/core/Types.h"

namespace tetskin::python {

namespace py = pybind11;

using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMap = Eigen::Map<const RowMatrixXd>;

// `value` as a C-contiguous float64 array of shape (n, columns): itself when
// it is one, else a converted copy of an array of real or whole numbers.
// Throws Error naming `name` for another shape, another kind (complex,
// text, objects) or a non-finite entry when `finite`.
py::array_t<double, py::array::c_style> realRows(py::handle value, const char* name,
                                                 py::ssize_t columns, bool finite = true);
// The same as a matrix (a copy: for the libraries' owning types).
Points3 points3(py::handle value, const char* name);
// An (n, columns) array of whole numbers (any integer type) that fit an int.
Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> intRows(py::handle value,
                                                                            const char* name,
                                                                            py::ssize_t columns);
// A 1-d sequence of whole numbers (node ids), each in [0, bound).
std::vector<int> idList(py::handle value, const char* name, Index bound, const std::string& what);

// A read-only view of `rows` x `columns` items at `data` (row stride
// `rowStride` items), kept alive by `owner`.
template <class T>
py::array view(const T* data, Index rows, Index columns, Index rowStride, py::handle owner) {
  py::array_t<T> array(
      {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)},
      {static_cast<py::ssize_t>(rowStride * sizeof(T)), static_cast<py::ssize_t>(sizeof(T))}, data,
      owner);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}
// A read-only view of a whole row-major matrix or a vector (1-d).
template <class Matrix>
py::array view(const Matrix& matrix, py::handle owner) {
  using T = typename Matrix::Scalar;
  if constexpr (Matrix::ColsAtCompileTime == 1) {
    py::array_t<T> array({static_cast<py::ssize_t>(matrix.size())}, {sizeof(T)}, matrix.data(),
                         owner);
    py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return array;
  } else {
    return view(matrix.data(), matrix.rows(), matrix.cols(), matrix.cols(), owner);
  }
}

// A writable array that owns `matrix` (moved, not copied).
template <class Matrix>
py::array owning(Matrix&& matrix) {
  using Plain = std::decay_t<Matrix>;
  using T = typename Plain::Scalar;
  auto* kept = new Plain(std::move(matrix));
  py::capsule owner(kept, [](void* p) { delete static_cast<Plain*>(p); });
  if constexpr (Plain::ColsAtCompileTime == 1)
    return py::array_t<T>({static_cast<py::ssize_t>(kept->size())}, {sizeof(T)}, kept->data(),
                          owner);
  else
    return py::array_t<T>(
        {static_cast<py::ssize_t>(kept->rows()), static_cast<py::ssize_t>(kept->cols())},
        {static_cast<py::ssize_t>(kept->cols() * sizeof(T)), static_cast<py::ssize_t>(sizeof(T))},
        kept->data(), owner);
}

}  // namespace tetskin::python
