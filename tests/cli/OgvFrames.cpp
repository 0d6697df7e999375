// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin_ogv_frames MOVIE.ogv [FIRST.png]: decodes an Ogg Theora movie
// with libtheora (not VTK, which only writes them) and prints "N frames,
// WxH, first and last frames differ|equal"; with FIRST.png, also how far
// the first frame's luma lies from that image's (the mean difference, in
// 255ths of the video range), which shows a frame turned upside down or
// shifted. Exit status 2 on a file it cannot decode. For the CLI tests of
// render's films.
#include <ogg/ogg.h>
#include <theora/theoradec.h>
#include <vtkImageData.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <vector>

#include "tetskin/vtkio/VtkFiles.h"

namespace {

// The luma plane of a decoded frame, row by row (its picture region).
std::vector<unsigned char> luma(const th_ycbcr_buffer planes, const th_info& info) {
  std::vector<unsigned char> y;
  const th_img_plane& p = planes[0];
  for (ogg_uint32_t row = info.pic_y; row < info.pic_y + info.pic_height; ++row) {
    const unsigned char* line = p.data + static_cast<std::ptrdiff_t>(row) * p.stride + info.pic_x;
    y.insert(y.end(), line, line + info.pic_width);
  }
  return y;
}

// The mean difference between a decoded frame's luma (top row first) and
// the BT.601 video-range luma of `image` (VTK's rows: bottom first).
double meanLumaDifference(const std::vector<unsigned char>& decoded, unsigned width,
                          unsigned height, vtkImageData* image) {
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] != static_cast<int>(width) || dims[1] != static_cast<int>(height)) return 255;
  double sum = 0;
  for (unsigned row = 0; row < height; ++row)
    for (unsigned x = 0; x < width; ++x) {
      const int y = static_cast<int>(height - 1 - row);
      auto channel = [&](int c) {
        return image->GetScalarComponentAsDouble(static_cast<int>(x), y, 0, c);
      };
      const double lumaOfImage =
          16 + 219 * (0.299 * channel(0) + 0.587 * channel(1) + 0.114 * channel(2)) / 255;
      sum += std::abs(lumaOfImage - decoded[row * width + x]);
    }
  return sum / (static_cast<double>(width) * height);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: tetskin_ogv_frames MOVIE.ogv [FIRST.png]\n");
    return 2;
  }
  std::ifstream file(argv[1], std::ios::binary);
  if (!file) {
    std::fprintf(stderr, "error: %s: cannot open\n", argv[1]);
    return 2;
  }
  ogg_sync_state sync;
  ogg_sync_init(&sync);
  ogg_stream_state stream;
  bool streaming = false;
  th_info info;
  th_info_init(&info);
  th_comment comment;
  th_comment_init(&comment);
  th_setup_info* setup = nullptr;
  th_dec_ctx* decoder = nullptr;
  int headers = 0, frames = 0;
  std::vector<unsigned char> first, last;
  bool broken = false;
  while (file && !broken) {
    char* buffer = ogg_sync_buffer(&sync, 4096);
    file.read(buffer, 4096);
    ogg_sync_wrote(&sync, static_cast<long>(file.gcount()));
    ogg_page page;
    while (!broken && ogg_sync_pageout(&sync, &page) == 1) {
      if (!streaming) {
        ogg_stream_init(&stream, ogg_page_serialno(&page));
        streaming = true;
      }
      ogg_stream_pagein(&stream, &page);
      ogg_packet packet;
      while (!broken && ogg_stream_packetout(&stream, &packet) == 1) {
        if (headers < 3) {
          if (th_decode_headerin(&info, &comment, &setup, &packet) <= 0) {
            broken = true;
            break;
          }
          if (++headers == 3) decoder = th_decode_alloc(&info, setup);
          continue;
        }
        ogg_int64_t granule = 0;
        const int result = th_decode_packetin(decoder, &packet, &granule);
        if (result != 0 && result != TH_DUPFRAME) {
          broken = true;
          break;
        }
        th_ycbcr_buffer planes;
        th_decode_ycbcr_out(decoder, planes);
        last = luma(planes, info);
        if (frames++ == 0) first = last;
      }
    }
  }
  const bool decoded = !broken && headers == 3 && decoder;
  if (decoder) th_decode_free(decoder);
  th_setup_free(setup);
  th_comment_clear(&comment);
  if (streaming) ogg_stream_clear(&stream);
  ogg_sync_clear(&sync);
  if (!decoded) {
    std::fprintf(stderr, "error: %s: not an Ogg Theora movie libtheora decodes\n", argv[1]);
    th_info_clear(&info);
    return 2;
  }
  std::printf("%d frames, %ux%u, first and last frames %s\n", frames, info.pic_width,
              info.pic_height, first == last ? "equal" : "differ");
  if (argc == 3) {
    try {
      const double difference =
          meanLumaDifference(first, info.pic_width, info.pic_height, tetskin::readPng(argv[2]));
      std::printf("first frame %s the image (mean luma difference %.1f)\n",
                  difference < 1.5 ? "matches" : "differs from", difference);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      th_info_clear(&info);
      return 2;
    }
  }
  th_info_clear(&info);
  return 0;
}
