// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Ogg Theora movies (render's and the GUI's films) decoded with libtheora,
// which VTK does not read: for tests of what a film holds.

#include <vtkSmartPointer.h>

#include <filesystem>
#include <vector>

class vtkImageData;

namespace tetskin::test {

struct DecodedMovie {
  int frames = 0;
  unsigned width = 0, height = 0;
  // The luma planes of the first and last frames (top row first).
  std::vector<unsigned char> firstLuma, lastLuma;
};

// Throws std::runtime_error naming the file when libtheora cannot decode it.
DecodedMovie decodeMovie(const std::filesystem::path& path);

// The mean difference between a decoded frame's luma and the BT.601
// video-range luma of `image` (VTK's rows, bottom first), in 255ths; 255
// when the sizes differ. A frame encoded from the image lies within about
// 1; another frame of the same run, or the image upside down, further.
double meanLumaDifference(const std::vector<unsigned char>& luma, unsigned width, unsigned height,
                          vtkImageData* image);

}  // namespace tetskin::test
