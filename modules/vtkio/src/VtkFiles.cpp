// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/VtkFiles.h"

#include <png.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <array>
#include <atomic>
#include <fstream>
#include <string>

#include "VtkXmlHeader.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/PartitionedSurface.h"
#include "tetskin/vtkio/VtkErrorCapture.h"

namespace tetskin {
namespace {

std::atomic<VtkCompression> compression{VtkCompression::LZ4};

template <typename Writer, typename Data>
void writeXml(const std::filesystem::path& path, Data* data) {
  writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<Writer>::New();
    VtkErrorCapture errors(writer);
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(data);
    writer->SetDataModeToAppended();
    switch (compression.load()) {
      case VtkCompression::None:
        writer->SetCompressorTypeToNone();
        break;
      case VtkCompression::ZLib:
        writer->SetCompressorTypeToZLib();
        break;
      case VtkCompression::LZ4:
        writer->SetCompressorTypeToLZ4();
        break;
    }
    if (!writer->Write() || errors.failed())
      throw Error(path.string(), 0, "cannot write: " + errors.message());
  });
}

// (`allowEmpty`: a piece of a .pvtp may hold no points.)
template <typename Reader, typename Data>
vtkSmartPointer<Data> readXml(const std::filesystem::path& path, std::string_view type,
                              bool allowEmpty = false) {
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  detail::checkVtkXmlData(path, detail::checkVtkXmlHeader(path, type));
  auto reader = vtkSmartPointer<Reader>::New();
  VtkErrorCapture errors(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<Data> out = reader->GetOutput();
  if (errors.failed() || !out || (!allowEmpty && out->GetNumberOfPoints() == 0))
    throw Error(path.string(), 0, errors.message("contains no points"));
  return out;
}

}  // namespace

void setVtkCompression(VtkCompression value) {
  compression = value;
}
VtkCompression vtkCompression() {
  return compression;
}

void writeVtp(const std::filesystem::path& path, vtkPolyData* data) {
  writeXml<vtkXMLPolyDataWriter>(path, data);
}

void writeVtu(const std::filesystem::path& path, vtkUnstructuredGrid* data) {
  writeXml<vtkXMLUnstructuredGridWriter>(path, data);
}
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path) {
  if (lowerExtension(path) == ".pvtp") return readPvtp(path);
  return readXml<vtkXMLPolyDataReader, vtkPolyData>(path, "PolyData");
}
vtkSmartPointer<vtkPolyData> detail::readVtpPiece(const std::filesystem::path& path) {
  return readXml<vtkXMLPolyDataReader, vtkPolyData>(path, "PolyData", true);
}
vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& path) {
  return readXml<vtkXMLUnstructuredGridReader, vtkUnstructuredGrid>(path, "UnstructuredGrid");
}

void writePng(const std::filesystem::path& path, vtkImageData* image) {
  // (libpng would refuse it deep inside, and VTK report that as a full disk.)
  if (!image || image->GetNumberOfPoints() == 0)
    throw Error(path.string(), 0, "no image to write (the render produced no pixels)");
  writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) throw Error(path.string(), 0, "cannot write the PNG image");
  });
}

// Through libpng's simplified API, not vtkPNGReader: VTK 9.1's reader
// crashes (a double free in its clean-up) on any PNG whose data libpng
// rejects, e.g. one cut short.
vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const auto failed = [&](const std::string& what) {
    const std::string reason = png.message;
    png_image_free(&png);
    return Error(path.string(), 0, what + (reason.empty() ? "" : " (" + reason + ")"));
  };
  std::array<png_byte, 8> signature{};
  std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(signature.data()), 8);
  if (png_sig_cmp(signature.data(), 0, 8) != 0) throw failed("is not a PNG image");
  if (!png_image_begin_read_from_file(&png, path.c_str())) throw failed("is a damaged PNG image");
  // 16-bit data would be taken as linear and converted to sRGB on the way
  // to 8 bits: refused rather than silently changed.
  if (png.format & PNG_FORMAT_FLAG_LINEAR)
    throw failed("must have 8 bits per channel (this one has 16)");
  constexpr png_uint_32 kMaxEdge = 32768;
  if (png.width > kMaxEdge || png.height > kMaxEdge)
    throw failed("is " + std::to_string(png.width) + " x " + std::to_string(png.height) +
                 " pixels; at most " + std::to_string(kMaxEdge) + " on a side are read");
  // Grey and palette images come out as RGB (with alpha where they have it).
  const bool alpha = (png.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  png.format = alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(static_cast<int>(png.width), static_cast<int>(png.height), 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, alpha ? 4 : 3);
  // A negative stride stores the rows bottom-up: VTK's image origin is the
  // lower left corner.
  if (!png_image_finish_read(&png, nullptr, image->GetScalarPointer(),
                             -static_cast<png_int_32>(PNG_IMAGE_ROW_STRIDE(png)), nullptr))
    throw failed("is a damaged PNG image");
  png_image_free(&png);
  return image;
}

}  // namespace tetskin
