// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Atomic VTK XML writers (.vtp, .vtu) and checked readers, for exports that
// ParaView opens; PNG images (screenshots, textures).

#include <vtkSmartPointer.h>

#include <filesystem>

#include "tetskin/core/OptionSchema.h"

class vtkImageData;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace tetskin {

// How the .vtp/.vtu writers compress their (appended, raw) data. LZ4 is the
// default: a bunny_64k binding (doc/benchmarks.md, "Output compression")
// was written 4.6x faster than with zlib and read 2.3x faster, for a file
// 26% larger; ParaView reads all three.
enum class VtkCompression { None, ZLib, LZ4 };
template <>
struct EnumSchema<VtkCompression> {
  static constexpr const char* what = "compression";
  static constexpr EnumValue<VtkCompression> values[] = {
      {VtkCompression::None, "none", "raw bytes, the largest files"},
      {VtkCompression::ZLib, "zlib", "the smallest files, slowest to write and read"},
      {VtkCompression::LZ4, "lz4", "fast to write and read"}};
};
inline constexpr EnumOption<VtkCompression> kCompressOption{
    "compress", "--compress", "the compression", "data of the .vtp/.vtu files written: "};
// The compression of every .vtp/.vtu written from now on, in this process
// (the command line's --compress); LZ4 unless set.
void setVtkCompression(VtkCompression compression);
VtkCompression vtkCompression();

void writeVtp(const std::filesystem::path& path, vtkPolyData* data);
void writeVtu(const std::filesystem::path& path, vtkUnstructuredGrid* data);
// A .vtp, or a .pvtp read whole (readPvtp).
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path);
vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& path);
void writePng(const std::filesystem::path& path, vtkImageData* image);
// An 8-bit RGB or RGBA image (grey and palette images become RGB), rows
// bottom-up as VTK's; throws Error naming the file for anything else or a
// damaged file.
vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path);

}  // namespace tetskin
