// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/VtkFiles.h"

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "VtkErrorCapture.h"
#include "VtkXmlHeader.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

template <typename Writer, typename Data>
void writeXml(const std::filesystem::path& path, Data* data) {
  writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<Writer>::New();
    detail::VtkErrorCapture errors(writer);
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(data);
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    if (!writer->Write() || errors.failed())
      throw Error(path.string(), 0, "cannot write: " + errors.message());
  });
}

template <typename Reader, typename Data>
vtkSmartPointer<Data> readXml(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  detail::checkVtkXmlHeader(path);
  auto reader = vtkSmartPointer<Reader>::New();
  detail::VtkErrorCapture errors(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<Data> out = reader->GetOutput();
  if (errors.failed() || !out || out->GetNumberOfPoints() == 0)
    throw Error(path.string(), 0, errors.message("contains no points"));
  return out;
}

}  // namespace

void writeVtp(const std::filesystem::path& path, vtkPolyData* data) {
  writeXml<vtkXMLPolyDataWriter>(path, data);
}
void writeVtu(const std::filesystem::path& path, vtkUnstructuredGrid* data) {
  writeXml<vtkXMLUnstructuredGridWriter>(path, data);
}
vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path) {
  return readXml<vtkXMLPolyDataReader, vtkPolyData>(path);
}
vtkSmartPointer<vtkUnstructuredGrid> readVtu(const std::filesystem::path& path) {
  return readXml<vtkXMLUnstructuredGridReader, vtkUnstructuredGrid>(path);
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

vtkSmartPointer<vtkImageData> readPng(const std::filesystem::path& path) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  if (!reader->CanReadFile(path.c_str())) throw Error(path.string(), 0, "is not a PNG image");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (image->GetScalarType() != VTK_UNSIGNED_CHAR || image->GetNumberOfScalarComponents() < 3)
    throw Error(path.string(), 0, "must be an 8-bit RGB or RGBA image");
  return image;
}

}  // namespace tetskin
