// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Runs drawn by `tetskin render`: a recorded run (--run) frame by frame,
// to images (OUT_00000.png, ...) or into one movie (.ogv), on the level its
// frames are of, framed on its whole motion; and a simulated run (--frames)
// filmed as it runs.

#include <cstddef>
#include <filesystem>
#include <string>

#include "AnimatedScene.h"
#include "SurfaceInput.h"
#include "tetskin/core/TetMesh.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/vtkio/RecordedRun.h"

namespace tetskin::cli {

// The level a run's frames are of (their Level array; where the first frame
// has none, --level's), which --level and a binding must not contradict.
int runLevel(const RecordedRun& recorded, const SurfaceInput& input, const Dataset& dataset,
             int levelOption, bool levelGiven);

// OUT.png -> OUT_00007.png: the image of the run's frame `index`.
std::filesystem::path frameImage(const std::filesystem::path& output, std::size_t index);

// Draws every control frame of a recorded run to its own image, replacing
// the images of an earlier drawing under the same name; a frame that cannot
// be drawn removes the images drawn before it, and the folders made for them.
void drawRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest);

// Films a recorded run: every control frame into one movie (.ogv), written
// atomically (nothing is left where a frame cannot be drawn).
void filmRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest);

// Simulates and draws `frames` frames of the scene into the movie `output`
// (.ogv, written atomically), at 1/dt frames/s; the stats leave the
// encoding out.
FrameStats filmSimulation(AnimatedScene& scene, int frames, const std::filesystem::path& output);

}  // namespace tetskin::cli
