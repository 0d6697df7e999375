// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin_ogv_frames MOVIE.ogv [FIRST.png]: decodes an Ogg Theora movie
// with libtheora (MovieDecoding.h) and prints "N frames, WxH, first and
// last frames differ|equal"; with FIRST.png, also whether the first frame
// is that image (mean luma difference below 1.5 of 255), which shows a
// frame turned upside down or shifted. Exit status 2 on a file it cannot
// decode. For the CLI tests of render's films.
#include <vtkImageData.h>

#include <cstdio>
#include <exception>

#include "MovieDecoding.h"
#include "tetskin/vtkio/VtkFiles.h"

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: tetskin_ogv_frames MOVIE.ogv [FIRST.png]\n");
    return 2;
  }
  try {
    using namespace tetskin;
    const test::DecodedMovie movie = test::decodeMovie(argv[1]);
    std::printf("%d frames, %ux%u, first and last frames %s\n", movie.frames, movie.width,
                movie.height, movie.firstLuma == movie.lastLuma ? "equal" : "differ");
    if (argc == 3) {
      const double difference =
          test::meanLumaDifference(movie.firstLuma, movie.width, movie.height, readPng(argv[2]));
      std::printf("first frame %s the image (mean luma difference %.1f)\n",
                  difference < 1.5 ? "matches" : "differs from", difference);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
