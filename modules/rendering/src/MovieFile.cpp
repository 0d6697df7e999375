// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/MovieFile.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkOggTheoraWriter.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {

int movieRate(double secondsPerFrame) {
  if (!(secondsPerFrame > 0)) return 1;
  return static_cast<int>(std::clamp(std::lround(1 / secondsPerFrame), 1L, 1000L));
}

MovieFile::MovieFile(std::filesystem::path path, int framesPerSecond)
    : path_(std::move(path)), writer_(vtkSmartPointer<vtkOggTheoraWriter>::New()) {
  writer_->SetFileName(path_.c_str());
  writer_->SetRate(framesPerSecond);
  writer_->SetQuality(2);  // the best: researchers' films are looked at closely
}

MovieFile::~MovieFile() {
  if (frames_ > 0 && !finished_) writer_->End();  // (the caller removes the file)
}

void MovieFile::check(const char* what) const {
  if (writer_->GetErrorCode() != vtkErrorCode::NoError)
    throw Error(path_.string(), 0,
                std::string("the movie encoder failed ") + what + ": " +
                    vtkErrorCode::GetStringFromErrorCode(writer_->GetErrorCode()));
}

void MovieFile::add(vtkImageData* frame) {
  int dims[3];
  frame->GetDimensions(dims);
  if (frame->GetScalarType() != VTK_UNSIGNED_CHAR || frame->GetNumberOfScalarComponents() < 3)
    throw Error(path_.string(), 0, "a movie frame must be an 8-bit RGB image");
  if (frames_ == 0) {
    width_ = dims[0];
    height_ = dims[1];
    // 4:2:0 chroma, the common layout, needs even sides; else 4:4:4.
    writer_->SetSubsampling(width_ % 2 == 0 && height_ % 2 == 0);
    writer_->SetInputData(frame);
    writer_->Start();
    check("starting");
  } else if (dims[0] != width_ || dims[1] != height_) {
    throw Error(path_.string(), 0,
                "frame " + std::to_string(frames_) + " is " + std::to_string(dims[0]) + "x" +
                    std::to_string(dims[1]) + ", the movie " + std::to_string(width_) + "x" +
                    std::to_string(height_));
  }
  writer_->SetInputData(frame);
  writer_->Write();
  check(("at frame " + std::to_string(frames_)).c_str());
  ++frames_;
}

void MovieFile::finish() {
  if (frames_ == 0) throw Error(path_.string(), 0, "a movie needs at least one frame");
  writer_->End();
  finished_ = true;
  check("ending the stream");
}

void writeMovieAtomically(const std::filesystem::path& target, int framesPerSecond,
                          const std::function<void(MovieFile&)>& addFrames) {
  writeFileAtomically(target, [&](const std::filesystem::path& temporary) {
    MovieFile movie(temporary, framesPerSecond);
    addFrames(movie);
    movie.finish();
  });
}

}  // namespace tetskin
