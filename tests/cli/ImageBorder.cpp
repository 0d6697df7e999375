// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin_image_border IMAGE.png [top]: exit status 0 when nothing drawn
// touches the image's border (with `top`, its top edge alone: a floor may
// fill the rest), 1 when something does (the side is named), 2 on a bad
// file. The background is a vertical gradient: untouched, each of the
// top and bottom rows is one colour, and the left and right columns are
// equal row by row. For the CLI tests of what a camera frames.
#include <vtkImageData.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "tetskin/vtkio/VtkFiles.h"

namespace {

int channelDifference(vtkImageData* image, int x0, int y0, int x1, int y1) {
  int largest = 0;
  for (int c = 0; c < image->GetNumberOfScalarComponents() && c < 3; ++c) {
    const int a = static_cast<int>(image->GetScalarComponentAsDouble(x0, y0, 0, c));
    const int b = static_cast<int>(image->GetScalarComponentAsDouble(x1, y1, 0, c));
    largest = std::max(largest, std::abs(a - b));
  }
  return largest;
}

}  // namespace

int main(int argc, char** argv) {
  const bool topOnly = argc == 3 && std::string(argv[2]) == "top";
  if (argc != 2 && !topOnly) {
    std::fprintf(stderr, "usage: tetskin_image_border IMAGE.png [top]\n");
    return 2;
  }
  try {
    vtkSmartPointer<vtkImageData> image = tetskin::readPng(argv[1]);
    int dims[3];
    image->GetDimensions(dims);
    const int w = dims[0], h = dims[1];
    constexpr int kTolerance = 2;  // (the gradient's dithering)
    for (int x = 1; x < w; ++x) {
      if (!topOnly && channelDifference(image, x, 0, 0, 0) > kTolerance) {
        std::printf("%s: drawn at the bottom edge, x %d\n", argv[1], x);
        return 1;
      }
      if (channelDifference(image, x, h - 1, 0, h - 1) > kTolerance) {
        std::printf("%s: drawn at the top edge, x %d\n", argv[1], x);
        return 1;
      }
    }
    for (int y = 0; y < h && !topOnly; ++y)
      if (channelDifference(image, 0, y, w - 1, y) > kTolerance) {
        std::printf("%s: drawn at the left or right edge, y %d\n", argv[1], y);
        return 1;
      }
    std::printf("%s: the %s is background\n", argv[1], topOnly ? "top edge" : "border");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
