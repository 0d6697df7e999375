// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A command's --surface (render, simulate): any surface file, bound anew to
// the command's level (closest, normal offset), or a binding written by
// `tetskin bind`, used as it is (its method, offset and level).

#include <filesystem>
#include <optional>

#include "tetskin/binding/BindingSummary.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/SurfaceMesh.h"
#include "tetskin/core/TetMesh.h"

namespace tetskin::cli {

struct SurfaceInput {
  std::filesystem::path path;
  SurfaceMesh surface;
  std::optional<SurfaceBinding> binding;  // from the file, checked against the dataset
};

// (Warns as warnOfNormalGaps does.)
SurfaceInput readSurfaceInput(const std::filesystem::path& path, const MultiLevelTetMesh& dataset);

// "warning: PATH: 1 triangle of zero area ..." on stderr where the surface
// has vertices without a normal (NormalGaps): it binds all the same (a
// binding needs positions only), but they are drawn unlit.
void warnOfNormalGaps(const std::filesystem::path& path, const SurfaceMesh& surface);

// "warning: PATH: a tenth of the vertices lie more than ..." on stderr where
// the binding's misfitWarning speaks. Returns the binding's summary.
BindingSummary warnOfMisfit(const std::filesystem::path& path, const SurfaceMesh& surface,
                            const SurfaceBinding& binding, const MultiLevelTetMesh& dataset);

// The level the command works on: the binding's, if the input is one, else
// --level's (`levelOption`, resolveLevel). Throws Error when --level was
// given (`levelGiven`) and names another level than the binding's.
int commandLevel(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int levelOption,
                 bool levelGiven);

// The input's binding, or its surface bound to `level` (warning as
// warnOfMisfit does; a binding from a file was warned about when bind made it).
SurfaceBinding bindingAt(const SurfaceInput& input, const MultiLevelTetMesh& dataset, int level);

}  // namespace tetskin::cli
