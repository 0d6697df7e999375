// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A simulation run as a ParaView time series: RUN.pvd plus RUN_frames/ with
// one control-mesh .vtu (and optionally one bound-surface .vtp) per frame,
// or the bound surface's frames alone, or several bound surfaces' frames;
// a run of several bodies writes each body's control mesh and skin as parts
// of their own (2k and 2k + 1 for body k); a run with obstacles adds them
// as posed at each frame (the parts after the bodies': 2, 3, ... for one).
// The .pvd is rewritten after every frame, so a run stopped at any point
// leaves a valid series. Used by `tetskin simulate` and the GUI's recorder.

#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/FloorPlane.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SimulationFrame.h"

namespace tetskin {

// An obstacle as a frame shows it: its surface in its own coordinates, the
// map to the world's at the frame's time, and whether that map changes over
// the run (a static obstacle's file is written once and named by every frame).
struct PosedSurface {
  const SurfaceMesh* surface = nullptr;
  Eigen::Affine3d toWorld = Eigen::Affine3d::Identity();
  bool moves = false;
};

class RunRecorder {
 public:
  // `pvd` gets the .pvd extension if it lacks it; creates RUN_frames/, or
  // removes the frames of an earlier run written there (and its .pvd).
  // The run's `conditions` (its floor, if any, and prescribed nodes) go
  // into every control frame (SimulationFrame.h), so that the run is drawn
  // with them. With `surfacePieces` > 1, each surface frame is a .pvtp in
  // that many pieces (PartitionedSurface.h), cut the same way in every frame
  // (restPieces of the first); the control mesh, small and needed whole by
  // every rank, stays one .vtu.
  explicit RunRecorder(std::filesystem::path pvd, RunConditions conditions = {},
                       int surfacePieces = 1);
  // The folder the frames of a run written to `pvd` go to (RUN_frames/).
  static std::filesystem::path framesDirectory(const std::filesystem::path& pvd);
  const std::filesystem::path& path() const { return series_.path(); }
  Index frames() const { return frames_; }
  // The control level's state (level-local nodes; SimulationFrame.h) and,
  // if given, the bound surface already deformed to this frame, and the
  // obstacles posed at it: obstacle K is part 2 + K, in
  // obstacle_K.vtp (static) or obstacle_NNNNN_K.vtp (moving). With
  // `bodies` (the level and the surface as a union of them, BodyUnion.h),
  // body k's part of the level is part 2k (control_NNNNN_k.vtu, nodes
  // numbered from the body's first), its part of the surface part 2k + 1
  // (surface_NNNNN_k.vtp), and obstacle K part 2 #bodies + K.
  void addFrame(double time, const TetMesh& rest, const FrameFields& fields, int level,
                const BoundSurface* deformedSurface = nullptr,
                std::span<const PosedSurface> obstacles = {},
                std::span<const BodyRange> bodies = {});
  // The first part the obstacles take: after one body's two, and after
  // `bodies` bodies' two each.
  static constexpr int kFirstObstaclePart = 2;
  static constexpr int firstObstaclePart(int bodies) { return bodies > 1 ? 2 * bodies : 2; }
  // A frame of the bound surface alone (part 1, as beside a control frame):
  // `tetskin deform` of a recorded run.
  void addSurfaceFrame(double time, const BoundSurface& deformedSurface);
  // A frame of several bound surfaces, one part each in the given order
  // (surface_NNNNN_K.vtp for part K): `tetskin compare`'s levels.
  void addSurfacesFrame(double time, const std::vector<const BoundSurface*>& deformedSurfaces);

 private:
  std::filesystem::path framesDirectory_;  // absolute
  PvdSeries series_;
  RunConditions conditions_;
  int surfacePieces_ = 1;
  std::vector<std::vector<SurfacePiece>> piecesOfPart_;  // with surfacePieces_ > 1
  Index frames_ = 0;
  std::vector<bool> staticObstacleWritten_;  // per obstacle

  // Writes this frame's surface file and adds it to the series (unwritten).
  void addSurface(double time, const BoundSurface& deformedSurface);
  // Writes `surface` as the frame's file `stem` + .vtp (or .pvtp in pieces)
  // and adds it to the series as `part`.
  void writeSurface(double time, int part, const std::string& stem, const BoundSurface& surface);
  // Writes obstacle `k` as posed at this frame (a static one the first time
  // only) and adds it to the series.
  void addObstacle(double time, int part, std::size_t k, const PosedSurface& obstacle);
};

}  // namespace tetskin
