// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A run recorded by `tetskin simulate` or the GUI's Record (.pvd), opened
// to be drawn, deformed or stepped through: its control-mesh frames (part 0;
// a surface's frames beside them are left out) in time order, each read on
// demand and checked against the level it is applied to. A run of several
// bodies (a scene's: body k's control mesh is part 2k, RunRecorder.h) is
// read as their union (BodyUnion.h): each frame the bodies' frames of one
// time side by side, body after body, as the scene's run stepped them.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tetskin/core/BodyUnion.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SimulationFrame.h"

namespace tetskin {

class RecordedRun {
 public:
  // Throws Error naming the .pvd when it is no series, has no control-mesh
  // frames or names a frame file that is not there, or when its bodies'
  // frames are not at the same times.
  explicit RecordedRun(const std::filesystem::path& pvd);

  const std::filesystem::path& path() const { return path_; }
  std::size_t frameCount() const { return frames_.size(); }
  double time(std::size_t frame) const { return frames_.at(frame).time; }
  // The mean time between frames (31 frames over 1 s: 1/30 s); 0 for one.
  double meanFrameSeconds() const;
  // The frame's file, as found from the .pvd's folder.
  const std::string& file(std::size_t frame) const { return frames_.at(frame).file; }
  // The dataset level the frames are of (the first frame's Level array);
  // nullopt where it does not say.
  std::optional<int> level() const { return level_; }
  // The bodies the run recorded (1 for a run of one body), and where each
  // lies in the union read() reads: its nodes and elements (the skin's
  // ranges are left 0: the skins are parts of their own).
  int bodyCount() const { return static_cast<int>(bodies_.size()); }
  const std::vector<BodyRange>& bodies() const { return bodies_; }
  // The run's floor (the first frame's FloorNormal and FloorHeight);
  // nullopt for a run without one, or one recorded before floors were.
  std::optional<FloorPlane> floor() const { return conditions_.floor; }
  // The nodes whose motion the run prescribed (the first frame's
  // Prescribed array; the union's numbering for several bodies), sorted;
  // empty for none, or a run recorded before frames said.
  const std::vector<int>& prescribedNodes() const { return conditions_.prescribedNodes; }
  // The run's first surface frame (part 1: the bound surface deformed, a
  // binding that names its dataset), as found from the .pvd's folder (not
  // checked to be there); none for a run recorded without a surface, or
  // of several bodies (each body's skin is a part of its own: their scene
  // gives the skins and their binding).
  const std::optional<std::string>& surfaceFile() const { return surface_; }
  // The mesh the run's frames are of, at rest: its first frame less its
  // displacements (readFrameRest), the bodies' side by side for several.
  TetMesh rest() const;
  // The state of frame `frame` of the mesh `rest` (named `restName` in
  // messages); throws Error naming the frame's file as readSimulationFrame,
  // and for several bodies naming the .pvd where `rest` has other node or
  // element counts than the bodies together.
  FrameState read(std::size_t frame, const TetMesh& rest, const std::string& restName) const;

 private:
  std::filesystem::path path_;
  std::vector<PvdSeries::Entry> frames_;                   // body 0's for several
  std::vector<std::vector<PvdSeries::Entry>> bodyFrames_;  // several bodies: each's
  std::vector<BodyRange> bodies_;
  std::optional<int> level_;
  RunConditions conditions_;
  std::optional<std::string> surface_;
};

}  // namespace tetskin
