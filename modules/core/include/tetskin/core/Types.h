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

// Rows owned elsewhere (a Points3, or a VTK array's buffer seen through an
// Eigen::Map), so a kernel reads or writes them where they are, uncopied.
using Points3Ref = Eigen::Ref<Points3>;
using ConstPoints3Ref = Eigen::Ref<const Points3>;

}  // namespace tetskin
