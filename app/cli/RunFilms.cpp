// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RunFilms.h"

#include <vtkImageData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tetskin/core/Error.h"
#include "tetskin/core/Geometry.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/rendering/MovieFile.h"
#include "tetskin/rendering/OffscreenView.h"

namespace tetskin::cli {
namespace {

// Frames the camera on the run's whole motion, so that no frame leaves the
// picture (a drop's start lies above the rest shape): every frame is read
// (and checked) once before any is drawn. The run's floor, if it recorded
// one, is drawn under it.
void setUpForRun(AnimatedScene& scene, const RecordedRun& recorded, const TetMesh& rest,
                 const std::string& restName) {
  BoundingBox motion;
  for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
    const BoundingBox box = boundingBox(recorded.read(i, rest, restName).positions);
    motion.extend(box.min);
    motion.extend(box.max);
  }
  scene.frame(motion);
  if (recorded.floor()) scene.showFloor(*recorded.floor());
}

// Draws frame `i` of the run (the fur's drag from the time since the one before).
void drawFrame(AnimatedScene& scene, const RecordedRun& recorded, std::size_t i,
               const TetMesh& rest, const std::string& restName) {
  const FrameState state = recorded.read(i, rest, restName);
  scene.draw(state.positions, recorded.time(i),
             i > 0 ? recorded.time(i) - recorded.time(i - 1) : 0);
}

}  // namespace

// The level a run's frames are of (their Level array; where the first frame
// has none, --level's), which --level and a binding must not contradict.
int runLevel(const RecordedRun& recorded, const SurfaceInput& input, const Dataset& dataset,
             int levelOption, bool levelGiven) {
  if (!recorded.level()) return commandLevel(input, dataset.mesh, levelOption, levelGiven);
  const int level = *recorded.level();
  if (level < 0 || level >= static_cast<int>(dataset.mesh.levels.size()))
    throw Error(recorded.file(0), 0,
                "is a frame of level " + std::to_string(level) + "; the dataset has " +
                    std::to_string(dataset.mesh.levels.size()) + " level(s)");
  if (levelGiven && resolveLevel(dataset.mesh, levelOption) != level)
    throw Error(std::string(kLevelOption.flag) + " " + std::to_string(levelOption) +
                ": the run's frames are of level " + std::to_string(level) + "; leave --level out");
  if (input.binding && input.binding->level != level)
    throw Error(input.path.string(), 0,
                "is bound to level " + std::to_string(input.binding->level) +
                    ", the run's frames are of level " + std::to_string(level) +
                    ": bind the surface to level " + std::to_string(level) +
                    " or give the plain surface");
  return level;
}

// OUT.png -> OUT_00007.png: the image of the run's frame `index`.
std::filesystem::path frameImage(const std::filesystem::path& output, std::size_t index) {
  char number[16];
  std::snprintf(number, sizeof number, "_%05zu", index);
  std::filesystem::path image = output;
  image.replace_filename(output.stem().string() + number + output.extension().string());
  return image;
}

// Draws every control frame of a recorded run to its own image, replacing
// the images of an earlier drawing under the same name; a frame that cannot
// be drawn removes the images drawn before it, and the folders made for them.
void drawRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest) {
  requireWritableLocation(frameImage(output, 0));
  const std::filesystem::path madeFolder = outermostMissingFolder(output);  // (the images make it)
  setUpForRun(scene, recorded, rest, restName);
  std::vector<std::filesystem::path> written;
  try {
    for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
      drawFrame(scene, recorded, i, rest, restName);
      written.push_back(frameImage(output, i));
      scene.view().writePng(written.back());
    }
  } catch (...) {
    for (const std::filesystem::path& image : written) std::filesystem::remove(image);
    if (!madeFolder.empty()) std::filesystem::remove_all(madeFolder);
    throw;
  }
  // The images of an earlier, longer run drawn under this name would follow
  // this run's in a film made of the folder's images.
  for (std::size_t i = recorded.frameCount(); std::filesystem::exists(frameImage(output, i)); ++i)
    std::filesystem::remove(frameImage(output, i));
}

// Films a recorded run: every control frame into one movie (.ogv), written
// atomically (nothing is left where a frame cannot be drawn).
void filmRun(AnimatedScene& scene, const RecordedRun& recorded, const std::filesystem::path& output,
             const std::string& restName, const TetMesh& rest) {
  requireWritableLocation(output);
  setUpForRun(scene, recorded, rest, restName);
  writeMovieAtomically(output, movieRate(recorded.meanFrameSeconds()), [&](MovieFile& movie) {
    for (std::size_t i = 0; i < recorded.frameCount(); ++i) {
      drawFrame(scene, recorded, i, rest, restName);
      movie.add(scene.view().capture());
    }
  });
}

FrameStats filmSimulation(AnimatedScene& scene, int frames, const std::filesystem::path& output) {
  FrameStats stats;
  writeMovieAtomically(output, movieRate(scene.frameSeconds()), [&](MovieFile& movie) {
    stats = scene.run(frames, [&] { movie.add(scene.view().capture()); });
  });
  return stats;
}

}  // namespace tetskin::cli
