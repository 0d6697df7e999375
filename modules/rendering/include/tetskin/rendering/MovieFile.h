// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A movie of rendered frames: Ogg Theora (.ogv), the video format Debian's
// VTK writes (vtkOggTheoraWriter). Frames are added one by one at a fixed
// rate. The file is written as it goes: writeMovieAtomically (below) makes
// the whole movie atomic.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <functional>

class vtkImageData;
class vtkOggTheoraWriter;

namespace tetskin {

// A movie's rate for frames `seconds` apart, so that it plays in real time
// (1/60 s: 60 frames/s); 1 to 1000.
int movieRate(double secondsPerFrame);

class MovieFile {
 public:
  MovieFile(std::filesystem::path path, int framesPerSecond);
  MovieFile(const MovieFile&) = delete;
  MovieFile& operator=(const MovieFile&) = delete;
  ~MovieFile();

  // An 8-bit RGB or RGBA image (OffscreenView::capture), every one the
  // size of the first. Throws Error naming the file when one is not, or
  // the encoder fails.
  void add(vtkImageData* frame);
  // Ends the stream; throws Error naming the file when no frame was added
  // or the encoder fails.
  void finish();
  int frames() const { return frames_; }

 private:
  std::filesystem::path path_;
  vtkSmartPointer<vtkOggTheoraWriter> writer_;
  int width_ = 0, height_ = 0, frames_ = 0;
  bool finished_ = false;

  void check(const char* what) const;
};

// Writes the movie `target` atomically at `framesPerSecond`: addFrames adds
// its frames, and what it throws leaves no file (and no folder made for it).
void writeMovieAtomically(const std::filesystem::path& target, int framesPerSecond,
                          const std::function<void(MovieFile&)>& addFrames);

}  // namespace tetskin
