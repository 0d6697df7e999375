// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/SurfaceFile.h"

#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>

#include <cstdint>
#include <fstream>
#include <string>

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

// vtkSTLReader takes a file for binary as vtksys's DetectFileType does (5%
// or more of its first 256 bytes outside printable ASCII, tab, newline and
// return; an empty file too), and then allocates for the triangle count at
// byte 80 before it reads a triangle. A binary file must hold that many
// 50-byte triangles after its 84-byte header: one that does not is refused
// here, before VTK allocates what it claims (19 GB for a 100-byte file
// starting "solid", found by fuzz_stl).
void checkBinaryStlSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char head[256];
  in.read(head, sizeof head);
  const std::streamsize read = in.gcount();
  std::streamsize text = 0;
  for (std::streamsize i = 0; i < read; ++i) {
    const auto c = static_cast<unsigned char>(head[i]);
    if ((c >= 0x20 && c <= 0x7F) || c == '\n' || c == '\r' || c == '\t') ++text;
  }
  if (read > 0 && static_cast<double>(read - text) < 0.05 * static_cast<double>(read)) return;
  const std::uintmax_t size = std::filesystem::file_size(path);
  if (size < 84)
    throw Error(path.string(), 0,
                "a binary STL starts with an 84-byte header and triangle count; the file has " +
                    std::to_string(size) + " bytes");
  const auto* bytes = reinterpret_cast<const unsigned char*>(head);
  const std::uint64_t count = std::uint64_t{bytes[80]} | std::uint64_t{bytes[81]} << 8 |
                              std::uint64_t{bytes[82]} << 16 | std::uint64_t{bytes[83]} << 24;
  if (84 + 50 * count > size)
    throw Error(path.string(), 0,
                "a binary STL of " + std::to_string(count) + " triangles needs " +
                    std::to_string(84 + 50 * count) + " bytes; the file has " +
                    std::to_string(size) + " (truncated, or not an STL)");
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
  if (e == ".stl") {
    if (std::filesystem::is_regular_file(path)) checkBinaryStlSize(path);
    return readWithVtk<vtkSTLReader>(path);
  }
  if (e == ".vtp" || e == ".pvtp") return fromVtkPolyData(readVtp(path), path.string());
  throw Error(path.string(), 0,
              "unknown surface format '" + e + "' (expected .obj, .ply, .stl, .vtp or .pvtp)");
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
