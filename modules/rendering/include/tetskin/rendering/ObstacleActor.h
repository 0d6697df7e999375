// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// An obstacle as an actor: its closed surface in its own coordinates,
// drawn translucent (the body behind and inside it stays in view) and
// posed by an affine map that changes per frame without copying the
// surface (the actor's user matrix).

#include <Eigen/Geometry>
#include <memory>

#include "tetskin/core/Geometry.h"
#include "tetskin/core/SurfaceMesh.h"

class vtkActor;

namespace tetskin {

class ObstacleActor {
 public:
  // Throws Error for a surface without triangles.
  explicit ObstacleActor(const SurfaceMesh& surface);
  ~ObstacleActor();
  vtkActor* actor() const;
  // Where the surface's own coordinates lie in the world's.
  void setPose(const Eigen::Affine3d& toWorld);
  // The posed surface's box (its corners' box mapped, so at most a little
  // larger under a rotation).
  BoundingBox bounds() const;

  static constexpr double kOpacity = 0.35;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
