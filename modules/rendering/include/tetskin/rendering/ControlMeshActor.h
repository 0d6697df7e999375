// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The control mesh of one level as an actor: surface, wireframe or shrunken
// tetrahedra, following the simulated positions.

#include <vtkSmartPointer.h>

#include <memory>
#include <string_view>

#include "tetskin/core/TetMesh.h"

class vtkActor;

namespace tetskin {

enum class ControlMeshStyle { Surface, Wireframe, ShrunkenTets };
// "surface", "wireframe", "shrink"; throws Error otherwise.
ControlMeshStyle parseControlMeshStyle(std::string_view name);

class ControlMeshActor {
 public:
  ControlMeshActor(const TetMesh& rest, ControlMeshStyle style);
  ~ControlMeshActor();
  vtkActor* actor() const;
  // Level-local node positions.
  void update(const Points3& positions);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
