// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The control mesh of one level as an actor: surface, wireframe or shrunken
// tetrahedra, following the simulated positions.

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <optional>
#include <string_view>

#include "tetskin/core/TetMesh.h"

class vtkActor;

namespace tetskin {

enum class ControlMeshStyle { Surface, Wireframe, ShrunkenTets };
// The names the command line and the GUI offer: "none" (no control mesh
// drawn), "surface", "wireframe", "shrink".
inline constexpr std::array<const char*, 4> kControlMeshStyleNames = {"none", "surface",
                                                                      "wireframe", "shrink"};
// One of kControlMeshStyleNames ("none": nullopt); throws Error otherwise.
std::optional<ControlMeshStyle> parseControlMeshStyle(std::string_view name);

class ControlMeshActor {
 public:
  ControlMeshActor(const TetMesh& rest, ControlMeshStyle style);
  ~ControlMeshActor();
  vtkActor* actor() const;
  // Level-local node positions, one row per node of `rest` (throws Error
  // otherwise).
  void update(const ConstPoints3Ref& positions);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
