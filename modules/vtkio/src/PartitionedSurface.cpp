// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/PartitionedSurface.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>

#include "VtkXmlHeader.h"
#include "XmlText.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/vtkio/VtkErrorCapture.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

constexpr const char* kPointIds = "GlobalPointIds";
constexpr const char* kCellIds = "GlobalCellIds";
// A .pvtp is a list of file names: far below this for any real one.
constexpr std::uintmax_t kMaxSummaryBytes = 16u << 20;

vtkSmartPointer<vtkIdList> idList(const std::vector<Index>& ids) {
  auto list = vtkSmartPointer<vtkIdList>::New();
  list->SetNumberOfIds(static_cast<vtkIdType>(ids.size()));
  for (std::size_t i = 0; i < ids.size(); ++i) list->SetId(static_cast<vtkIdType>(i), ids[i]);
  return list;
}

vtkSmartPointer<vtkIdList> identityList(vtkIdType count) {
  auto list = vtkSmartPointer<vtkIdList>::New();
  list->SetNumberOfIds(count);
  for (vtkIdType i = 0; i < count; ++i) list->SetId(i, i);
  return list;
}

vtkSmartPointer<vtkIdTypeArray> idArray(const char* name, const std::vector<Index>& ids) {
  auto array = vtkSmartPointer<vtkIdTypeArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(ids.size()));
  std::copy(ids.begin(), ids.end(), array->GetPointer(0));
  return array;
}

// One piece of `whole`: its triangles renumbered to its own points.
// `local` (one entry per point of whole) is scratch, reused across pieces.
vtkSmartPointer<vtkPolyData> extractPiece(vtkPolyData* whole, const SurfacePiece& piece,
                                          std::vector<vtkIdType>& local) {
  auto out = vtkSmartPointer<vtkPolyData>::New();
  const auto pointCount = static_cast<vtkIdType>(piece.vertices.size());
  const auto cellCount = static_cast<vtkIdType>(piece.triangles.size());
  const vtkSmartPointer<vtkIdList> pointIds = idList(piece.vertices);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(whole->GetPoints()->GetDataType());
  points->SetNumberOfPoints(pointCount);
  whole->GetPoints()->GetData()->GetTuples(pointIds, points->GetData());
  out->SetPoints(points);
  out->GetPointData()->CopyAllocate(whole->GetPointData(), pointCount);
  out->GetPointData()->CopyData(whole->GetPointData(), pointIds, identityList(pointCount));
  out->GetPointData()->SetGlobalIds(idArray(kPointIds, piece.vertices));

  for (vtkIdType i = 0; i < pointCount; ++i) local[static_cast<std::size_t>(piece.vertices[i])] = i;
  vtkCellArray* polys = whole->GetPolys();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateEstimate(cellCount, 3);
  auto cellPoints = vtkSmartPointer<vtkIdList>::New();
  for (Index t : piece.triangles) {
    polys->GetCellAtId(t, cellPoints);
    for (vtkIdType c = 0; c < cellPoints->GetNumberOfIds(); ++c)
      cellPoints->SetId(c, local[static_cast<std::size_t>(cellPoints->GetId(c))]);
    cells->InsertNextCell(cellPoints);
  }
  out->SetPolys(cells);
  out->GetCellData()->CopyAllocate(whole->GetCellData(), cellCount);
  out->GetCellData()->CopyData(whole->GetCellData(), idList(piece.triangles),
                               identityList(cellCount));
  out->GetCellData()->SetGlobalIds(idArray(kCellIds, piece.triangles));
  out->GetFieldData()->ShallowCopy(whole->GetFieldData());
  return out;
}

// The XML word VTK writes for an array's value type.
std::string xmlType(vtkAbstractArray* array) {
  switch (array->GetDataType()) {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      return "Int8";
    case VTK_UNSIGNED_CHAR:
      return "UInt8";
    case VTK_SHORT:
      return "Int16";
    case VTK_UNSIGNED_SHORT:
      return "UInt16";
    case VTK_INT:
      return "Int32";
    case VTK_UNSIGNED_INT:
      return "UInt32";
    case VTK_FLOAT:
      return "Float32";
    case VTK_DOUBLE:
      return "Float64";
    case VTK_STRING:
      return "String";
    case VTK_UNSIGNED_LONG:
    case VTK_UNSIGNED_LONG_LONG:
      return "UInt64";
    default:
      return "Int64";  // long, long long, vtkIdType (64-bit in Debian's VTK)
  }
}

// <PPointData ...> or <PCellData ...>: each array's name, type and
// components, and which array is which attribute (Normals, GlobalIds, ...).
void writeArrayList(std::ostream& out, const char* element, vtkDataSetAttributes* data) {
  out << "    <" << element;
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
    if (vtkAbstractArray* array = data->GetAbstractAttribute(a); array && array->GetName())
      out << ' ' << vtkDataSetAttributes::GetAttributeTypeAsString(a) << "=\""
          << detail::xmlEscaped(array->GetName()) << '"';
  out << ">\n";
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    out << "      <PDataArray type=\"" << xmlType(array) << "\" Name=\""
        << detail::xmlEscaped(array->GetName() ? array->GetName() : "")
        << "\" NumberOfComponents=\"" << array->GetNumberOfComponents() << "\"/>\n";
  }
  out << "    </" << element << ">\n";
}

void writeSummary(const std::filesystem::path& path, vtkPolyData* firstPiece, int pieces) {
  writeTextAtomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <PPolyData GhostLevel=\"0\">\n";
    writeArrayList(out, "PPointData", firstPiece->GetPointData());
    writeArrayList(out, "PCellData", firstPiece->GetCellData());
    out << "    <PPoints>\n      <PDataArray type=\"" << xmlType(firstPiece->GetPoints()->GetData())
        << "\" Name=\"Points\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (int p = 0; p < pieces; ++p)
      out << "    <Piece Source=\"" << detail::xmlEscaped(pvtpPieceName(path, p)) << "\"/>\n";
    out << "  </PPolyData>\n</VTKFile>\n";
  });
}

// Pieces with global ids, merged back into the surface they were cut from.
vtkSmartPointer<vtkPolyData> mergePieces(const std::filesystem::path& path,
                                         const std::vector<vtkSmartPointer<vtkPolyData>>& pieces,
                                         const std::vector<std::filesystem::path>& files) {
  // The whole's sizes: the largest ids + 1, each id checked to be there.
  vtkIdType pointCount = 0, cellCount = 0, piecePoints = 0, pieceCells = 0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    piecePoints += pieces[p]->GetNumberOfPoints();
    pieceCells += pieces[p]->GetNumberOfCells();
    const auto check = [&](vtkDataArray* ids, const char* what) {
      vtkIdType top = -1;
      for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i) {
        const auto id = static_cast<vtkIdType>(ids->GetComponent(i, 0));
        if (id < 0) throw Error(files[p].string(), 0, std::string(what) + " holds a negative id");
        top = std::max(top, id);
      }
      return top + 1;
    };
    pointCount =
        std::max(pointCount, check(pieces[p]->GetPointData()->GetArray(kPointIds), kPointIds));
    cellCount = std::max(cellCount, check(pieces[p]->GetCellData()->GetArray(kCellIds), kCellIds));
    if (pieces[p]->GetNumberOfVerts() + pieces[p]->GetNumberOfLines() +
            pieces[p]->GetNumberOfStrips() >
        0)
      throw Error(files[p].string(), 0, "a surface piece may hold polygons only");
  }
  // (Ids past what the pieces hold would leave gaps: refused before they
  // are allocated for.)
  if (pointCount > piecePoints || cellCount > pieceCells)
    throw Error(path.string(), 0,
                "its pieces' global ids reach " + std::to_string(pointCount) + " points and " +
                    std::to_string(cellCount) + " cells; the pieces hold " +
                    std::to_string(piecePoints) + " and " + std::to_string(pieceCells));
  vtkPolyData* first = pieces.front();
  auto whole = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(first->GetPoints() ? first->GetPoints()->GetDataType() : VTK_FLOAT);
  points->SetNumberOfPoints(pointCount);
  whole->SetPoints(points);
  // Every array of the first piece, sized for the whole (the ids left out).
  const auto allocate = [](vtkDataSetAttributes* from, vtkDataSetAttributes* to, vtkIdType count,
                           const char* ids) {
    for (int i = 0; i < from->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* array = from->GetAbstractArray(i);
      if (!array->GetName() || std::string(array->GetName()) == ids) continue;
      vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(array->NewInstance());
      copy->SetName(array->GetName());
      copy->SetNumberOfComponents(array->GetNumberOfComponents());
      copy->SetNumberOfTuples(count);
      to->AddArray(copy);
      if (const int attribute = from->IsArrayAnAttribute(i); attribute >= 0)
        to->SetActiveAttribute(array->GetName(), attribute);
    }
  };
  allocate(first->GetPointData(), whole->GetPointData(), pointCount, kPointIds);
  allocate(first->GetCellData(), whole->GetCellData(), cellCount, kCellIds);
  // Copies each piece's tuples to their global ids.
  const auto scatter = [](vtkDataSetAttributes* from, vtkDataSetAttributes* to, vtkIdList* source,
                          vtkIdList* target, const std::filesystem::path& file) {
    for (int i = 0; i < to->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* array = to->GetAbstractArray(i);
      vtkAbstractArray* own = from->GetAbstractArray(array->GetName());
      if (!own || own->GetNumberOfComponents() != array->GetNumberOfComponents() ||
          own->GetDataType() != array->GetDataType())
        throw Error(file.string(), 0,
                    std::string("lacks the array '") + array->GetName() +
                        "' as the first piece has it (name, type, components)");
      array->InsertTuples(target, source, own);
    }
  };
  std::vector<char> havePoint(static_cast<std::size_t>(pointCount), 0);
  std::vector<char> haveCell(static_cast<std::size_t>(cellCount), 0);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfTuples(cellCount + 1);
  std::vector<vtkIdType> sizes(static_cast<std::size_t>(cellCount), 0);
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    vtkPolyData* piece = pieces[p];
    const vtkIdType n = piece->GetNumberOfPoints(), m = piece->GetNumberOfCells();
    vtkDataArray* pointIds = piece->GetPointData()->GetArray(kPointIds);
    vtkDataArray* cellIds = piece->GetCellData()->GetArray(kCellIds);
    if (pointIds->GetNumberOfTuples() != n || cellIds->GetNumberOfTuples() != m)
      throw Error(files[p].string(), 0, "its global ids are not one per point and cell");
    auto target = vtkSmartPointer<vtkIdList>::New();
    target->SetNumberOfIds(n);
    for (vtkIdType i = 0; i < n; ++i) {
      target->SetId(i, static_cast<vtkIdType>(pointIds->GetComponent(i, 0)));
      havePoint[static_cast<std::size_t>(target->GetId(i))] = 1;
    }
    const vtkSmartPointer<vtkIdList> source = identityList(n);
    if (n > 0) {
      points->GetData()->InsertTuples(target, source, piece->GetPoints()->GetData());
      scatter(piece->GetPointData(), whole->GetPointData(), source, target, files[p]);
    }
    auto cellTarget = vtkSmartPointer<vtkIdList>::New();
    cellTarget->SetNumberOfIds(m);
    for (vtkIdType c = 0; c < m; ++c) {
      const auto id = static_cast<vtkIdType>(cellIds->GetComponent(c, 0));
      cellTarget->SetId(c, id);
      haveCell[static_cast<std::size_t>(id)] = 1;
      sizes[static_cast<std::size_t>(id)] = piece->GetPolys()->GetCellSize(c);
    }
    if (m > 0)
      scatter(piece->GetCellData(), whole->GetCellData(), identityList(m), cellTarget, files[p]);
  }
  const auto gap = [&](const std::vector<char>& have, const char* what) {
    if (const auto it = std::find(have.begin(), have.end(), 0); it != have.end())
      throw Error(path.string(), 0,
                  "the pieces hold no " + std::string(what) + " " +
                      std::to_string(it - have.begin()) + " (their global ids leave a gap)");
  };
  gap(havePoint, "point");
  gap(haveCell, "cell");
  // The polygons, each at its global id, on global point ids.
  vtkIdType total = 0;
  for (vtkIdType c = 0; c < cellCount; ++c) {
    offsets->SetValue(c, total);
    total += sizes[static_cast<std::size_t>(c)];
  }
  offsets->SetValue(cellCount, total);
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfTuples(total);
  auto cellPoints = vtkSmartPointer<vtkIdList>::New();
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    vtkPolyData* piece = pieces[p];
    vtkDataArray* pointIds = piece->GetPointData()->GetArray(kPointIds);
    vtkDataArray* cellIds = piece->GetCellData()->GetArray(kCellIds);
    for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c) {
      piece->GetPolys()->GetCellAtId(c, cellPoints);
      const vtkIdType at = offsets->GetValue(static_cast<vtkIdType>(cellIds->GetComponent(c, 0)));
      for (vtkIdType k = 0; k < cellPoints->GetNumberOfIds(); ++k) {
        const vtkIdType point = cellPoints->GetId(k);
        if (point < 0 || point >= piece->GetNumberOfPoints())
          throw Error(files[p].string(), 0,
                      "polygon " + std::to_string(c) + " names point " + std::to_string(point) +
                          " of " + std::to_string(piece->GetNumberOfPoints()));
        connectivity->SetValue(at + k, static_cast<vtkIdType>(pointIds->GetComponent(point, 0)));
      }
    }
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, connectivity);
  whole->SetPolys(polys);
  whole->GetFieldData()->ShallowCopy(first->GetFieldData());
  return whole;
}

}  // namespace

std::string pvtpPieceName(const std::filesystem::path& path, int piece) {
  return path.stem().string() + "_piece" + std::to_string(piece) + ".vtp";
}

void writePvtp(const std::filesystem::path& path, vtkPolyData* whole,
               const std::vector<SurfacePiece>& pieces) {
  if (whole->GetNumberOfVerts() + whole->GetNumberOfLines() + whole->GetNumberOfStrips() > 0)
    throw Error(path.string(), 0, "only a surface of polygons is written in pieces");
  if (pieces.empty()) throw Error(path.string(), 0, "no pieces to write");
  // An earlier .pvtp at `path` goes first: cut short, this write would
  // otherwise leave it naming a mix of its own pieces and the new ones.
  std::filesystem::remove(path);
  std::vector<vtkIdType> local(static_cast<std::size_t>(whole->GetNumberOfPoints()), -1);
  const std::filesystem::path folder = path.parent_path();
  vtkSmartPointer<vtkPolyData> first;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const vtkSmartPointer<vtkPolyData> piece = extractPiece(whole, pieces[p], local);
    writeVtp(folder / pvtpPieceName(path, static_cast<int>(p)), piece);
    if (p == 0) first = piece;
  }
  writeSummary(path, first, static_cast<int>(pieces.size()));
  // An earlier write's further pieces, which this .pvtp no longer names.
  for (auto p = static_cast<int>(pieces.size());; ++p) {
    std::error_code ignored;
    if (!std::filesystem::remove(folder / pvtpPieceName(path, p), ignored)) break;
  }
}

std::vector<std::filesystem::path> pvtpPieceFiles(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error || !std::filesystem::is_regular_file(path))
    throw Error(path.string(), 0, "cannot open for reading");
  if (bytes > kMaxSummaryBytes)
    throw Error(path.string(), 0,
                "is " + std::to_string(bytes) + " bytes: more than a .pvtp's list of pieces");
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  VtkErrorCapture errors(parser);
  parser->SetFileName(path.c_str());
  if (!parser->Parse() || errors.failed())
    throw Error(path.string(), 0, errors.message("is not well-formed XML"));
  // (VTK keeps where an element starts, in bytes, not its line.)
  const auto lineOf = [&](vtkXMLDataElement* element) {
    const auto at = std::min<std::size_t>(
        static_cast<std::size_t>(std::max<vtkTypeInt64>(element->GetXMLByteIndex(), 0)),
        text.size());
    return 1 +
           static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  };
  vtkXMLDataElement* root = parser->GetRootElement();
  const char* type = root ? root->GetAttribute("type") : nullptr;
  vtkXMLDataElement* list = root ? root->FindNestedElementWithName("PPolyData") : nullptr;
  if (!root || std::string(root->GetName()) != "VTKFile" || !type ||
      std::string(type) != "PPolyData" || !list)
    throw Error(path.string(), root ? lineOf(root) : 0,
                "is no partitioned surface (a VTKFile of type PPolyData)");
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < list->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* piece = list->GetNestedElement(i);
    if (std::string(piece->GetName()) != "Piece") continue;
    const char* source = piece->GetAttribute("Source");
    if (!source || !*source)
      throw Error(path.string(), lineOf(piece), "a Piece names no Source file");
    files.push_back(path.parent_path() / source);
  }
  if (files.empty()) throw Error(path.string(), lineOf(list), "names no piece");
  return files;
}

vtkSmartPointer<vtkPolyData> readPvtp(const std::filesystem::path& path) {
  const std::vector<std::filesystem::path> files = pvtpPieceFiles(path);
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  bool globalIds = true;
  for (const std::filesystem::path& file : files) {
    pieces.push_back(detail::readVtpPiece(file));
    globalIds = globalIds && pieces.back()->GetPointData()->GetArray(kPointIds) &&
                pieces.back()->GetCellData()->GetArray(kCellIds);
  }
  vtkSmartPointer<vtkPolyData> whole;
  if (globalIds) {
    whole = mergePieces(path, pieces, files);
  } else {
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    for (const auto& piece : pieces) append->AddInputData(piece);
    append->Update();
    whole = append->GetOutput();
    whole->GetFieldData()->ShallowCopy(pieces.front()->GetFieldData());
  }
  if (whole->GetNumberOfPoints() == 0)
    throw Error(path.string(), 0, "its pieces contain no points");
  return whole;
}

}  // namespace tetskin
