// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/SurfaceFile.h"

#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>

#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/io/PlyFormat.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkErrorCapture.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

template <typename Reader>
SurfaceMesh readWithVtk(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  auto reader = vtkSmartPointer<Reader>::New();
  VtkErrorCapture errors(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (errors.failed() || reader->GetOutput()->GetNumberOfPolys() == 0)
    throw Error(path.string(), 0, errors.message("contains no triangles"));
  return fromVtkPolyData(reader->GetOutput(), path.string());
}

template <typename Writer>
void writeWithVtk(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  vtkSmartPointer<vtkPolyData> data = toVtkPolyData(mesh);
  writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = vtkSmartPointer<Writer>::New();
    VtkErrorCapture errors(writer);
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(data);
    writer->SetFileTypeToBinary();
    if (!writer->Write() || errors.failed())
      throw Error(path.string(), 0, "cannot write: " + errors.message());
  });
}

}  // namespace

bool isSurfaceFile(const std::filesystem::path& path) {
  const std::string e = lowerExtension(path);
  return e == ".obj" || e == ".ply" || e == ".stl" || e == ".vtp";
}

SurfaceMesh readSurface(const std::filesystem::path& path) {
  const std::string e = lowerExtension(path);
  if (e == ".obj") return readObj(path);
  if (e == ".ply") return readPly(path);
  if (e == ".stl") return readWithVtk<vtkSTLReader>(path);
  if (e == ".vtp") return fromVtkPolyData(readVtp(path), path.string());
  throw Error(path.string(), 0,
              "unknown surface format '" + e + "' (expected .obj, .ply, .stl or .vtp)");
}

void writeSurface(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  validateSurface(mesh, path.string());
  const std::string e = lowerExtension(path);
  if (e == ".obj") return writeObj(path, mesh);
  if (e == ".ply") return writePly(path, mesh);
  if (e == ".stl") return writeWithVtk<vtkSTLWriter>(path, mesh);
  if (e == ".vtp") return writeVtp(path, toVtkPolyData(mesh));
  throw Error(path.string(), 0,
              "unknown surface format '" + e + "' (expected .obj, .ply, .stl or .vtp)");
}

}  // namespace tetskin
