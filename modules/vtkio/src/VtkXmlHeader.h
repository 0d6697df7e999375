// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
#include <filesystem>
#include <string_view>

namespace tetskin::detail {

// Checks the XML part of a VTK XML file (.vtp, .vtu) before VTK's reader
// sees it: that reader crashes or hangs on some malformed attributes (an
// unknown or legacy array type such as 'Inx32' or 'IdType' in field data, a
// negative NumberOfPoints, float cell offsets, a point array declared
// String, 99999999999 components). Every Array/DataArray must have a known
// type (String on Array elements only), 1 to 4096 components and whole-number
// counts, cell offsets and connectivity an integer type, every Piece
// non-negative whole-number sizes. The root element must be a VTKFile of
// `expectedType` ("PolyData", "UnstructuredGrid"). Throws Error naming the
// file and line.
void checkVtkXmlHeader(const std::filesystem::path& path, std::string_view expectedType);

}  // namespace tetskin::detail
