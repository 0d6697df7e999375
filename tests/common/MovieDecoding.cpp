// SPDX-License-Identifier: AGPL-3.0-or-later
#include "MovieDecoding.h"

#include <ogg/ogg.h>
#include <theora/theoradec.h>
#include <vtkImageData.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace tetskin::test {
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

}  // namespace

DecodedMovie decodeMovie(const std::filesystem::path& path) {
  DecodedMovie movie;
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": cannot open");
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
  int headers = 0;
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
        movie.lastLuma = luma(planes, info);
        if (movie.frames++ == 0) movie.firstLuma = movie.lastLuma;
      }
    }
  }
  const bool decoded = !broken && headers == 3 && decoder;
  movie.width = info.pic_width;
  movie.height = info.pic_height;
  if (decoder) th_decode_free(decoder);
  th_setup_free(setup);
  th_comment_clear(&comment);
  th_info_clear(&info);
  if (streaming) ogg_stream_clear(&stream);
  ogg_sync_clear(&sync);
  if (!decoded)
    throw std::runtime_error(path.string() + ": not an Ogg Theora movie libtheora decodes");
  return movie;
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

}  // namespace tetskin::test
