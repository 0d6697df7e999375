// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Plain-data matrix types shared by every module. Row-major, so the rows of a
// matrix lie contiguously and a kernel can view them as std::span.

#include <Eigen/Core>
#include <cstdint>

namespace tetskin {

using Index = std::int64_t;
using Points3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Points2 = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Tetrahedra = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;

}  // namespace tetskin
