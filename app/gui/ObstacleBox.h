// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The box widget that places an obstacle while the run is paused: a VTK
// box (vtkBoxWidget2) around the obstacle's own bounds, posed as the
// obstacle is; dragging it moves, turning it rotates, and pulling its
// faces scales it, uniformly (an obstacle's scale is one number: the
// box's volume decides it, and the box snaps back to a cube's proportions
// of the obstacle's). Each change ends in `placed(k, pose)`.

#include <vtkBoxWidget2.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <optional>

#include "tetskin/simulation/Obstacle.h"

class vtkRenderWindowInteractor;
class vtkTransform;

namespace tetskin {
struct BoundingBox;
}

namespace tetskin::gui {

// The obstacle placement a box transform (local -> world, possibly with a
// scale along each of the box's axes) stands for: its translation, its
// rotation (the nearest to the transform's linear part) and the uniform
// scale of the same volume.
ObstaclePose poseOfBoxTransform(vtkTransform* transform);

class ObstacleBox {
 public:
  ObstacleBox(vtkRenderWindowInteractor* interactor,
              std::function<void(std::size_t, const ObstaclePose&)> placed);
  ~ObstacleBox();
  // Puts the box around obstacle k (its own `bounds`, posed by `pose`),
  // shown and live; hide() takes it away.
  void show(std::size_t k, const BoundingBox& bounds, const ObstaclePose& pose);
  void hide();
  std::optional<std::size_t> shownObstacle() const { return shown_; }
  vtkBoxWidget2* widget() const { return widget_; }
  // What an interaction's end does: the box's pose made uniform, shown so,
  // and reported (public for tests, which cannot drag).
  void finishInteraction();

 private:
  vtkSmartPointer<vtkBoxWidget2> widget_;
  std::function<void(std::size_t, const ObstaclePose&)> placed_;
  std::optional<std::size_t> shown_;
};

}  // namespace tetskin::gui
