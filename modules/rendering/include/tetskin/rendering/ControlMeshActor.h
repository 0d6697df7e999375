// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The control mesh of one level as an actor: surface, wireframe or shrunken
// tetrahedra, following the simulated positions.

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <optional>
#include <string_view>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/TetMesh.h"

class vtkActor;

namespace tetskin {

// How the control mesh is drawn; None: not at all.
enum class ControlMeshStyle { None, Surface, Wireframe, ShrunkenTets };
template <>
struct EnumSchema<ControlMeshStyle> {
  static constexpr const char* what = "control mesh style";
  static constexpr EnumValue<ControlMeshStyle> values[] = {
      {ControlMeshStyle::None, "none", ""},
      {ControlMeshStyle::Surface, "surface", ""},
      {ControlMeshStyle::Wireframe, "wireframe", ""},
      {ControlMeshStyle::ShrunkenTets, "shrink", "shrunken tetrahedra"}};
};
// (Its default differs on purpose: `render` draws none, an image of the
// skin; the GUI's View dock starts on wireframe, to show the cage it
// inspects.)
inline constexpr EnumOption<ControlMeshStyle> kControlMeshOption{
    "control", "--control", "the control mesh", "control mesh: "};

class ControlMeshActor {
 public:
  // `style` is not None (throws Error).
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
