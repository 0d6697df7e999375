// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tetskin::detail {

// Where a VTK XML file keeps one Array/DataArray's values, and how many the
// file's XML part says it has (what VTK's reader allocates before reading).
struct VtkXmlArray {
  enum class Role {
    Field,         // FieldData: its NumberOfTuples
    Sized,         // Points, PointData, CellData, a cell section's types and offsets
    Connectivity,  // a cell section's: as many as its offsets' last value
    Unsized,       // anything else (a .vtu's polyhedron faces)
  };
  std::string name;  // its Name, or "?"
  std::string type;  // Int32, Float64, String, Bit, ...
  long long components = 1;
  Role role = Role::Unsized;
  long long tuples = 0;                      // with Role::Field or Role::Sized
  std::string format;                        // ascii, binary (inline base64) or appended
  long long offset = 0;                      // appended: into the appended data
  std::uint64_t textBegin = 0, textEnd = 0;  // inline: the element's text, in bytes
  long line = 0;                             // of its tag
  int cellSection = -1;  // the index of its cell section (offsets, connectivity)
};

// What checkVtkXmlData needs of a file's XML part.
struct VtkXmlLayout {
  long rootLine = 0;    // of <VTKFile ...>
  int headerBytes = 4;  // header_type UInt32 (VTK's default) or UInt64
  bool bigEndian = false;
  std::string compressor;  // empty: the binary data is not compressed
  std::vector<VtkXmlArray> arrays;
  std::optional<std::uint64_t> appendedBegin;  // where <AppendedData ...>'s data start
  bool appendedBase64 = false;
};

// Checks the XML part of a VTK XML file (.vtp, .vtu) before VTK's reader
// sees it: that reader crashes or hangs on some malformed attributes (an
// unknown or legacy array type such as 'Inx32' or 'IdType' in field data, a
// negative NumberOfPoints, float cell offsets, a point array declared
// String, 99999999999 components). Every Array/DataArray must have a known
// type (String on Array elements only), 1 to 4096 components and whole-number
// counts, cell offsets and connectivity an integer type, every Piece
// non-negative whole-number sizes. The root element must be a VTKFile of
// `expectedType` ("PolyData", "UnstructuredGrid"). Throws Error naming the
// file and line. Returns where the file keeps its arrays.
VtkXmlLayout checkVtkXmlHeader(const std::filesystem::path& path, std::string_view expectedType);

// Checks that the file holds the values its XML part and its binary data's
// headers claim, before VTK's reader allocates for them: VTK 9.1 allocates
// what a header says (a compression header's block count and block sizes,
// an array's tuple count, a cell section's last offset) and only then finds
// the file too short, so a few corrupt bytes asked it for gigabytes. Each
// compression header must fit in the file, its blocks' compressed bytes
// too, and a block may not expand more than its compressor can (zlib 1032
// times, LZ4 255, LZMA about 7000); each array's data must hold at least the
// tuples it is allocated for. Throws Error naming the file, the array's line
// and what it claims against what the file has. It never refuses a file
// VTK reads completely.
void checkVtkXmlData(const std::filesystem::path& path, const VtkXmlLayout& layout);

// A .vtp checked and read as readVtp reads one, which may hold no points:
// a piece of a .pvtp.
vtkSmartPointer<vtkPolyData> readVtpPiece(const std::filesystem::path& path);

}  // namespace tetskin::detail
