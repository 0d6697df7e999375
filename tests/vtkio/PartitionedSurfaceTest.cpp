// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <fstream>
#include <sstream>
#include <string>

#include "ExpectError.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PartitionedSurface.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

// The bunny with point normals, a point array of ints, a point 3-vector
// of doubles, a cell array and a string in its field data: the kinds of
// arrays a deformed binding carries.
vtkSmartPointer<vtkPolyData> surfaceWithArrays() {
  SurfaceMesh mesh = readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj");
  mesh.normals = mesh.positions.rowwise().normalized();
  vtkSmartPointer<vtkPolyData> data = toVtkPolyData(mesh);
  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName("ControlIds");
  ids->SetNumberOfComponents(3);
  ids->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < ids->GetNumberOfValues(); ++i)
    ids->SetValue(i, static_cast<int>(i * 7));
  data->GetPointData()->AddArray(ids);
  auto displacement = vtkSmartPointer<vtkDoubleArray>::New();
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < displacement->GetNumberOfValues(); ++i)
    displacement->SetValue(i, 0.001 * static_cast<double>(i % 97));
  data->GetPointData()->AddArray(displacement);
  auto face = vtkSmartPointer<vtkIntArray>::New();
  face->SetName("Region");
  face->SetNumberOfTuples(data->GetNumberOfCells());
  for (vtkIdType c = 0; c < face->GetNumberOfValues(); ++c)
    face->SetValue(c, static_cast<int>(c % 5));
  data->GetCellData()->AddArray(face);
  auto dataset = vtkSmartPointer<vtkStringArray>::New();
  dataset->SetName("Dataset");
  dataset->InsertNextValue("bunny.json");
  data->GetFieldData()->AddArray(dataset);
  return data;
}

std::vector<SurfacePiece> piecesOf(vtkPolyData* data, int count) {
  const SurfaceMesh mesh = fromVtkPolyData(data, "surface");
  return splitSurface(mesh.vertexCount(), mesh.triangles,
                      surfacePieces(mesh.positions, mesh.triangles, count));
}

void expectSameArrays(vtkDataSetAttributes* a, vtkDataSetAttributes* b) {
  ASSERT_EQ(a->GetNumberOfArrays(), b->GetNumberOfArrays());
  for (int i = 0; i < a->GetNumberOfArrays(); ++i) {
    vtkDataArray* x = a->GetArray(i);
    vtkDataArray* y = b->GetArray(x->GetName());
    ASSERT_NE(y, nullptr) << x->GetName();
    EXPECT_EQ(x->GetDataType(), y->GetDataType()) << x->GetName();
    ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << x->GetName();
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
      ASSERT_EQ(x->GetVariantValue(v), y->GetVariantValue(v)) << x->GetName() << " value " << v;
  }
}

// Pieces read back whole give the surface they were cut from: every point,
// polygon and array value in the original order, the field data, which
// array is the normals; and VTK's own parallel reader reads them too.
TEST(PartitionedSurface, PiecesReadBackAsTheWholeSurface) {
  test::ScratchDir dir;
  const vtkSmartPointer<vtkPolyData> whole = surfaceWithArrays();
  writePvtp(dir / "s.pvtp", whole, piecesOf(whole, 3));
  EXPECT_EQ(dir.listing(), "s.pvtp\ns_piece0.vtp\ns_piece1.vtp\ns_piece2.vtp\n");
  EXPECT_EQ(pvtpPieceFiles(dir / "s.pvtp").size(), 3u);

  const vtkSmartPointer<vtkPolyData> back = readVtp(dir / "s.pvtp");
  ASSERT_EQ(back->GetNumberOfPoints(), whole->GetNumberOfPoints());
  ASSERT_EQ(back->GetNumberOfPolys(), whole->GetNumberOfPolys());
  for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(back->GetPoint(i)[c], whole->GetPoint(i)[c]) << "point " << i;
  auto a = vtkSmartPointer<vtkIdList>::New(), b = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < whole->GetNumberOfPolys(); ++c) {
    whole->GetPolys()->GetCellAtId(c, a);
    back->GetPolys()->GetCellAtId(c, b);
    ASSERT_EQ(a->GetNumberOfIds(), b->GetNumberOfIds());
    for (vtkIdType k = 0; k < a->GetNumberOfIds(); ++k) ASSERT_EQ(a->GetId(k), b->GetId(k));
  }
  expectSameArrays(whole->GetPointData(), back->GetPointData());
  expectSameArrays(whole->GetCellData(), back->GetCellData());
  ASSERT_NE(back->GetPointData()->GetNormals(), nullptr);
  EXPECT_STREQ(back->GetPointData()->GetNormals()->GetName(), "Normals");
  auto* dataset = vtkStringArray::SafeDownCast(back->GetFieldData()->GetAbstractArray("Dataset"));
  ASSERT_NE(dataset, nullptr);
  EXPECT_EQ(dataset->GetValue(0), "bunny.json");

  // ParaView's reader (VTK's): every triangle once, border points once per
  // piece, the global ids that say which are one.
  auto reader = vtkSmartPointer<vtkXMLPPolyDataReader>::New();
  reader->SetFileName((dir / "s.pvtp").c_str());
  reader->Update();
  vtkPolyData* read = reader->GetOutput();
  EXPECT_EQ(read->GetNumberOfPolys(), whole->GetNumberOfPolys());
  EXPECT_GT(read->GetNumberOfPoints(), whole->GetNumberOfPoints());
  EXPECT_LT(read->GetNumberOfPoints(), whole->GetNumberOfPoints() * 11 / 10);
  ASSERT_NE(read->GetPointData()->GetGlobalIds(), nullptr);
  EXPECT_NE(read->GetPointData()->GetArray("Displacement"), nullptr);
}

// A file name XML must escape ('&' is legal on disk): the summary names
// its pieces well-formed and reads back whole.
TEST(PartitionedSurface, NamesWithXmlCharactersReadBack) {
  test::ScratchDir dir;
  const vtkSmartPointer<vtkPolyData> whole = surfaceWithArrays();
  writePvtp(dir / "a&b.pvtp", whole, piecesOf(whole, 2));
  EXPECT_EQ(pvtpPieceFiles(dir / "a&b.pvtp").back(), dir / "a&b_piece1.vtp");
  const vtkSmartPointer<vtkPolyData> back = readVtp(dir / "a&b.pvtp");
  EXPECT_EQ(back->GetNumberOfPoints(), whole->GetNumberOfPoints());
  expectSameArrays(whole->GetPointData(), back->GetPointData());
  auto reader = vtkSmartPointer<vtkXMLPPolyDataReader>::New();
  reader->SetFileName((dir / "a&b.pvtp").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), whole->GetNumberOfPolys());
}

// A binding in pieces (readBinding, readSurface read .pvtp whole); written
// again in fewer pieces, the earlier write's further pieces go.
TEST(PartitionedSurface, BindingsAndSurfacesReadWholeAndRewritesLeaveNoStalePieces) {
  test::ScratchDir dir;
  const SurfaceMesh sphere = test::sphere({0, 0, 0}, 1.0);
  writeVtp(dir / "plain.vtp", toVtkPolyData(sphere));
  const SurfaceMesh read = readSurface(dir / "plain.vtp");
  writePvtp(dir / "s.pvtp", toVtkPolyData(sphere), piecesOf(toVtkPolyData(sphere), 4));
  const SurfaceMesh back = readSurface(dir / "s.pvtp");
  EXPECT_EQ(back.positions, read.positions);
  EXPECT_EQ(back.triangles, read.triangles);
  writePvtp(dir / "s.pvtp", toVtkPolyData(sphere), piecesOf(toVtkPolyData(sphere), 2));
  EXPECT_EQ(dir.listing(), "plain.vtp\ns.pvtp\ns_piece0.vtp\ns_piece1.vtp\n");
  EXPECT_EQ(readSurface(dir / "s.pvtp").triangles, read.triangles);
}

// A piece listed but missing, a .pvtp of another kind, global ids that
// leave a gap or reach past what the pieces hold: errors naming the file.
TEST(PartitionedSurface, BrokenPartitionsGiveErrorsNamingTheFile) {
  test::ScratchDir dir;
  const vtkSmartPointer<vtkPolyData> whole = surfaceWithArrays();
  writePvtp(dir / "s.pvtp", whole, piecesOf(whole, 3));
  std::ifstream in(dir / "s.pvtp");
  std::stringstream text;
  text << in.rdbuf();
  const std::string summary = text.str();

  std::filesystem::remove(dir / "s_piece2.vtp");
  test::expectErrorAt([&] { readVtp(dir / "s.pvtp"); }, (dir / "s_piece2.vtp").string(), 0,
                      "cannot open for reading");

  std::string other = summary;
  other.replace(other.find("type=\"PPolyData\""), 16, "type=\"PUnstructuredGrid\"");
  test::expectErrorAt([&] { readVtp(dir.write("other.pvtp", other)); },
                      (dir / "other.pvtp").string(), 2, "is no partitioned surface");
  test::expectErrorAt([&] { readVtp(dir.write("bad.pvtp", "<VTKFile")); },
                      (dir / "bad.pvtp").string(), 0, "");
  std::string none = summary;
  while (none.find("<Piece ") != std::string::npos) {
    const std::size_t at = none.find("<Piece ");
    none.erase(at, none.find("/>", at) + 2 - at);
  }
  test::expectErrorAt([&] { readVtp(dir.write("none.pvtp", none)); }, (dir / "none.pvtp").string(),
                      3, "names no piece");

  // Two pieces of three: the third's points and triangles are not there.
  std::string two = summary;
  const std::size_t third = two.find("<Piece Source=\"s_piece2.vtp\"/>");
  two.erase(third, std::string("<Piece Source=\"s_piece2.vtp\"/>").size());
  writePvtp(dir / "s.pvtp", whole, piecesOf(whole, 3));
  test::expectErrorAt([&] { readVtp(dir.write("two.pvtp", two)); }, (dir / "two.pvtp").string(), 0,
                      "global ids");

  // A piece whose ids claim a surface far larger than the pieces hold.
  const vtkSmartPointer<vtkPolyData> piece = readVtp(dir / "s_piece1.vtp");
  piece->GetPointData()->GetArray("GlobalPointIds")->SetComponent(0, 0, 1e12);
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(piece);
  writer->SetFileName((dir / "s_piece1.vtp").c_str());
  writer->Write();
  test::expectErrorAt([&] { readVtp(dir / "s.pvtp"); }, (dir / "s.pvtp").string(), 0,
                      "global ids reach");
}

// Pieces without global ids (another writer's) are appended, each with its
// own copy of the points it shares.
TEST(PartitionedSurface, PiecesWithoutGlobalIdsAreAppended) {
  test::ScratchDir dir;
  const SurfaceMesh sphere = test::sphere({0, 0, 0}, 1.0);
  writeVtp(dir / "a.vtp", toVtkPolyData(sphere));
  writeVtp(dir / "b.vtp", toVtkPolyData(test::box({3, 0, 0}, {4, 1, 1})));
  dir.write("ab.pvtp",
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"1.0\">\n"
            "<PPolyData GhostLevel=\"0\"><PPoints><PDataArray type=\"Float64\" "
            "NumberOfComponents=\"3\"/></PPoints>\n"
            "<Piece Source=\"a.vtp\"/><Piece Source=\"b.vtp\"/></PPolyData></VTKFile>\n");
  const SurfaceMesh both = readSurface(dir / "ab.pvtp");
  EXPECT_EQ(both.vertexCount(), sphere.vertexCount() + 8);
  EXPECT_EQ(both.triangleCount(), sphere.triangleCount() + 12);
}

}  // namespace
}  // namespace tetskin
