// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The simulation's floor as an actor: a grey square with grid lines, lying
// in the floor plane under a body, so that a drop is seen to land on it.

#include <memory>

#include "tetskin/core/FloorPlane.h"
#include "tetskin/core/Geometry.h"

class vtkActor;

namespace tetskin {

class FloorActor {
 public:
  // A square in `floor`'s plane centred under `body` (a box of the body at
  // rest), reaching its widest horizontal side beyond it on every side,
  // with ten grid cells along each edge. Throws Error for an empty or
  // non-finite box or a non-finite height.
  FloorActor(const FloorPlane& floor, const BoundingBox& body);
  ~FloorActor();
  vtkActor* actor() const;
  // The square's corners' box (flat along the up axis).
  BoundingBox bounds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
