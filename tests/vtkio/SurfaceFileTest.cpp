// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <random>

#include "ExpectError.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SurfaceFile.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

SurfaceMesh bunny() {
  return readObj(std::string(TETSKIN_SOURCE_DIR) + "/data/bunny.obj");
}

TEST(SurfaceFile, EveryFormatRoundTrips) {
  test::ScratchDir dir;
  const SurfaceMesh m = bunny();
  for (const char* name : {"b.obj", "b.ply", "b.stl", "b.vtp"}) {
    SCOPED_TRACE(name);
    writeSurface(dir / name, m);
    const SurfaceMesh back = readSurface(dir / name);
    EXPECT_EQ(back.triangleCount(), m.triangleCount());
    EXPECT_EQ(back.vertexCount(), m.vertexCount());
    // PLY and STL store floats.
    EXPECT_NEAR(surfaceArea(back), surfaceArea(m), 1e-5 * surfaceArea(m));
  }
  EXPECT_EQ(dir.listing(), "b.obj\nb.ply\nb.stl\nb.vtp\n");
}

TEST(SurfaceFile, BrokenFilesGiveErrorsNamingTheFile) {
  test::ScratchDir dir;
  std::string garbage;
  for (int i = 0; i < 1000; ++i) garbage.push_back(static_cast<char>((i * 31) % 256));
  for (const char* name : {"g.ply", "g.vtp", "g.obj"}) {
    SCOPED_TRACE(name);
    const auto path = dir.write(name, garbage);
    try {
      readSurface(path);
      FAIL();
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), path.string()) << e.what();
    }
  }
  dir.write("empty.stl", "");
  EXPECT_THROW(readSurface(dir / "empty.stl"), Error);
  // A binary STL (VTK's reader takes a file with 5% of its first 256 bytes
  // binary for one) whose count claims more triangles than it holds is
  // refused before VTK allocates for the count: here 4 billion triangles
  // (200 GB) claimed by 134 bytes.
  std::string truncated(84, '\0');
  truncated.replace(0, 6, "solid ");  // (binary files may start so too)
  truncated.replace(80, 4, "\xff\xff\xff\xff");
  truncated += std::string(50, '\0');
  EXPECT_EQ(test::errorText([&] { readSurface(dir.write("truncated.stl", truncated)); }),
            (dir / "truncated.stl").string() +
                ": a binary STL of 4294967295 triangles needs 214748364834 bytes; the file has "
                "134 (truncated, or not an STL)");
  EXPECT_THROW(readSurface(dir / "missing.ply"), Error);
  EXPECT_THROW(readSurface(dir / "x.abc"), Error);
}

TEST(VtkFiles, PngRoundTripsAndAnEmptyImageIsNamedNotWritten) {
  test::ScratchDir dir;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(4, 3, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < 4 * 3 * 3; ++i) pixels[i] = static_cast<unsigned char>(20 * i);
  writePng(dir / "a.png", image);
  const vtkSmartPointer<vtkImageData> back = readPng(dir / "a.png");
  int dims[3];
  back->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4);
  EXPECT_EQ(dims[1], 3);
  EXPECT_EQ(static_cast<unsigned char*>(back->GetScalarPointer())[7], 140);
  // A render that produced nothing (no OpenGL context): named, and no file.
  test::expectErrorAt([&] { writePng(dir / "empty.png", vtkSmartPointer<vtkImageData>::New()); },
                      (dir / "empty.png").string(), 0, "no image to write");
  EXPECT_EQ(dir.listing(), "a.png\n");
}

// VTK's own PNG reader crashed on every damaged texture tried; these must
// end in an Error naming the file (or, where the damage missed the pixels,
// an image of the right size). Grey images come out as RGB.
TEST(VtkFiles, DamagedPngsAreErrorsAndGreyBecomesRgb) {
  test::ScratchDir dir;
  auto grey = vtkSmartPointer<vtkImageData>::New();
  grey->SetDimensions(64, 48, 1);
  grey->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* pixels = static_cast<unsigned char*>(grey->GetScalarPointer());
  for (int i = 0; i < 64 * 48; ++i) pixels[i] = static_cast<unsigned char>((i * 7) % 251);
  writePng(dir / "grey.png", grey);
  const vtkSmartPointer<vtkImageData> rgb = readPng(dir / "grey.png");
  ASSERT_EQ(rgb->GetNumberOfScalarComponents(), 3);
  const auto* back = static_cast<const unsigned char*>(rgb->GetScalarPointer());
  EXPECT_EQ(back[3 * 100], pixels[100]);  // the same row order as VTK's
  EXPECT_EQ(back[3 * 100 + 2], pixels[100]);

  const std::string good = test::readText(dir / "grey.png");
  std::mt19937 random(5);
  int refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::string damaged = good;
    const auto at = [&](std::size_t size) {
      return std::uniform_int_distribution<std::size_t>(0, size - 1)(random);
    };
    if (trial % 2)
      damaged.resize(at(damaged.size()));
    else
      for (int k = 0; k < 1 + trial % 9; ++k)
        damaged[at(damaged.size())] = static_cast<char>(random());
    const auto path = dir.write("damaged.png", damaged);
    try {
      int dims[3];
      readPng(path)->GetDimensions(dims);
      EXPECT_EQ(dims[0] * dims[1], 64 * 48);
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), path.string());
      ++refused;
    }
  }
  EXPECT_GT(refused, 100);
  test::expectErrorAt([&] { readPng(dir.write("text.png", "not an image")); },
                      (dir / "text.png").string(), 0, "is not a PNG image");
}

// Attributes that crash VTK's XML reader (field data of an unknown or
// legacy type, a negative size) are refused first, with file and line.
TEST(VtkFiles, MalformedXmlAttributesAreRefusedBeforeVtkReadsThem) {
  test::ScratchDir dir;
  vtkSmartPointer<vtkPolyData> data = toVtkPolyData(bunny());
  auto level = vtkSmartPointer<vtkIntArray>::New();
  level->SetName("Level");
  level->InsertNextValue(2);
  data->GetFieldData()->AddArray(level);
  writeVtp(dir / "good.vtp", data);
  const std::string good = test::readText(dir / "good.vtp");
  const auto lineOf = [&](const std::string& text) {
    const auto at = good.find(text);
    EXPECT_NE(at, std::string::npos) << text;
    return 1 + static_cast<long>(std::count(good.begin(), good.begin() + at, '\n'));
  };
  const struct {
    const char* from;
    const char* to;
    const char* what;
  } cases[] = {
      {"type=\"Int32\" Name=\"Level\"", "type=\"Inx32\" Name=\"Level\"",
       "DataArray 'Level': unknown type 'Inx32'"},
      {"type=\"Int32\" Name=\"Level\"", "type=\"IdType\" Name=\"Level\"", "unknown type 'IdType'"},
      {"type=\"Float64\" Name=\"Points\"", "type=\"String\" Name=\"Points\"",
       "DataArray 'Points': type String (strings are Array elements)"},
      {"type=\"Int32\" Name=\"Level\"", "type=\"String\" Name=\"Level\"",
       "DataArray 'Level': type String"},
      {"Name=\"Points\" NumberOfComponents=\"3\"",
       "Name=\"Points\" NumberOfComponents=\"99999999999\"",
       "DataArray 'Points': NumberOfComponents '99999999999' is not a whole number in [1, 4096]"},
      // (VTK leaked the points array where they were not 3-vectors.)
      {"Name=\"Points\" NumberOfComponents=\"3\"", "Name=\"Points\" NumberOfComponents=\"2\"",
       "Points 'Points': NumberOfComponents '2' (points have 3)"},
      {"Name=\"Points\" NumberOfComponents=\"3\"", "Name=\"Points\"",
       "Points 'Points': no NumberOfComponents (points have 3)"},
      {"NumberOfPoints=\"1839\"", "NumberOfPoints=\"-1\"",
       "Piece: NumberOfPoints '-1' is not a whole number >= 0"},
      {"Name=\"Level\" NumberOfTuples=\"1\"", "Name=\"Level\" NumberOfTuples=\"x\"",
       "NumberOfTuples 'x' is not a whole number >= 0"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    std::string bad = good;
    const auto at = bad.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    bad.replace(at, std::strlen(c.from), c.to);
    const auto path = dir.write("bad.vtp", bad);
    test::expectErrorAt([&] { readVtp(path); }, path.string(), lineOf(c.from), c.what);
  }
  EXPECT_EQ(readVtp(dir / "good.vtp")->GetNumberOfPoints(), 1839);
  // Float cell offsets in a .vtu (VTK crashed); a point array of that name
  // is any other array.
  writeVtu(dir / "good.vtu", toVtkUnstructuredGrid(test::unitTetrahedron()));
  std::string vtu = test::readText(dir / "good.vtu");
  const auto offsets = vtu.find("\" Name=\"offsets\"");
  ASSERT_NE(offsets, std::string::npos);
  const auto type = vtu.rfind("type=\"", offsets) + 6;
  vtu.replace(type, offsets - type, "Float32");
  const auto path = dir.write("bad.vtu", vtu);
  test::expectErrorAt([&] { readVtu(path); }, path.string(),
                      1 + static_cast<long>(std::count(vtu.begin(), vtu.begin() + type, '\n')),
                      "Cells offsets: type 'Float32' is not an integer type");
}

// A file of another kind where a .vtp or .vtu belongs (a surface frame given
// as a control frame, a .pvd, an OBJ) is named by its kind, not by VTK's
// parser; comments and the XML declaration before the root are fine.
TEST(VtkFiles, AFileOfAnotherKindIsNamedByItsKind) {
  test::ScratchDir dir;
  writeVtp(dir / "surface.vtp", toVtkPolyData(bunny()));
  writeVtu(dir / "control.vtu", toVtkUnstructuredGrid(test::unitTetrahedron()));
  test::expectErrorAt([&] { readVtu(dir / "surface.vtp"); }, (dir / "surface.vtp").string(), 2,
                      "is a VTK PolyData (.vtp) file, not UnstructuredGrid (.vtu)");
  test::expectErrorAt([&] { readVtp(dir / "control.vtu"); }, (dir / "control.vtu").string(), 2,
                      "is a VTK UnstructuredGrid (.vtu) file, not PolyData (.vtp)");
  const auto series = dir.write("run.pvd",
                                "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
                                "version=\"0.1\">\n<Collection/>\n</VTKFile>\n");
  test::expectErrorAt([&] { readVtu(series); }, series.string(), 2,
                      "is a VTK Collection (.pvd) file, not UnstructuredGrid (.vtu) (a series: "
                      "give one of its files)");
  const auto obj = dir.write("bunny.obj", "# a surface\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::expectErrorAt([&] { readVtp(obj); }, obj.string(), 0,
                      "is not a VTK XML file (no <VTKFile> root element)");
  std::string commented = test::readText(dir / "surface.vtp");
  commented.insert(commented.find("<VTKFile"), "<!-- written by hand -->\n");
  EXPECT_EQ(readVtp(dir.write("commented.vtp", commented))->GetNumberOfPoints(), 1839);
}

// A foreign file with inline ASCII data (VTK's writer in ASCII mode, as
// other tools write): the check reads past megabytes of numbers between
// the tags, in chunks, and still names the line of a bad attribute after
// them; the good file reads.
TEST(VtkFiles, InlineAsciiDataIsReadPastToTheAttributesAfterIt) {
  test::ScratchDir dir;
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetThetaResolution(400);
  sphere->SetPhiResolution(400);
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputConnection(sphere->GetOutputPort());
  writer->SetDataModeToAscii();
  writer->SetFileName((dir / "ascii.vtp").string().c_str());
  ASSERT_EQ(writer->Write(), 1);
  std::string text = test::readText(dir / "ascii.vtp");
  const auto polys = text.find("<Polys>");
  ASSERT_NE(polys, std::string::npos);
  ASSERT_GT(polys, std::size_t{2} << 20);  // more than two of the check's 1 MiB chunks before
  EXPECT_EQ(readVtp(dir / "ascii.vtp")->GetNumberOfPoints(), 400 * 398 + 2);
  const auto offsets = text.find("Name=\"offsets\"", polys);
  ASSERT_NE(offsets, std::string::npos);
  const auto type = text.rfind("type=\"", offsets) + 6;
  text.replace(type, text.find('"', type) - type, "Float64");
  const auto path = dir.write("bad.vtp", text);
  test::expectErrorAt([&] { readVtp(path); }, path.string(),
                      1 + static_cast<long>(std::count(text.begin(), text.begin() + type, '\n')),
                      "Polys offsets: type 'Float64' is not an integer type");
}

// File names with XML's special characters are legal on disk: the .pvd
// escapes them, and reads back what was written.
TEST(PvdSeries, WrittenSeriesReadsBackWithAnyFileName) {
  test::ScratchDir dir;
  PvdSeries series(dir / "r&d.pvd");
  series.add(0.0, 0, "r&d_frames/control_00000.vtu");
  series.add(0.0, 1, "r&d_frames/\"<surface>\".vtp");
  series.add(1.0 / 60, 0, "r&d_frames/control_00001.vtu");
  series.write();
  const PvdSeries back = PvdSeries::read(dir / "r&d.pvd");
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.entries()[i].file, series.entries()[i].file);
    EXPECT_EQ(back.entries()[i].part, series.entries()[i].part);
    EXPECT_EQ(back.entries()[i].time, series.entries()[i].time);  // 17 digits: exact
  }
  test::expectErrorAt([&] { PvdSeries::read(dir.write("x.pvd", "<VTKFile type=\"PolyData\"/>")); },
                      (dir / "x.pvd").string(), 0, "is not a ParaView time series");
  test::expectErrorAt([&] { PvdSeries::read(dir.write("y.pvd", "<VTKFile")); },
                      (dir / "y.pvd").string(), 0, "is not a readable XML file");
}

TEST(SurfaceFile, VtuRoundTrip) {
  test::ScratchDir dir;
  const TetMesh m = test::unitTetrahedron();
  writeVtu(dir / "m.vtu", toVtkUnstructuredGrid(m));
  const TetMesh back = fromVtkUnstructuredGrid(readVtu(dir / "m.vtu"), "m.vtu");
  EXPECT_EQ(back.nodes, m.nodes);
  EXPECT_EQ(back.elements, m.elements);
}

// The writers compress with LZ4 unless told otherwise; each compression
// writes a file that reads back the same, and says which it is.
TEST(SurfaceFile, EachCompressionWritesAFileThatReadsBackTheSame) {
  EXPECT_EQ(vtkCompression(), VtkCompression::LZ4);
  test::ScratchDir dir;
  const SurfaceMesh m = bunny();
  for (const auto& [compression, compressor] :
       {std::pair{VtkCompression::None, ""},
        std::pair{VtkCompression::ZLib, "vtkZLibDataCompressor"},
        std::pair{VtkCompression::LZ4, "vtkLZ4DataCompressor"}}) {
    SCOPED_TRACE(toString(compression));
    setVtkCompression(compression);
    const auto path = dir / (std::string(toString(compression)) + ".vtp");
    writeSurface(path, m);
    std::ifstream in(path, std::ios::binary);
    std::string head(400, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    EXPECT_EQ(head.find("compressor="),
              *compressor ? head.find(compressor) - 12 : std::string::npos)
        << head;
    const SurfaceMesh back = readSurface(path);
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.triangles, m.triangles);
  }
  setVtkCompression(VtkCompression::LZ4);
  EXPECT_LT(std::filesystem::file_size(dir / "zlib.vtp"),
            std::filesystem::file_size(dir / "lz4.vtp"));
  EXPECT_LT(std::filesystem::file_size(dir / "lz4.vtp"),
            std::filesystem::file_size(dir / "none.vtp"));
}

TEST(SurfaceFile, AssimpPlyAndStlCorpus) {
  const std::filesystem::path corpus = "/usr/share/assimp/models";
  if (!std::filesystem::is_directory(corpus)) GTEST_SKIP() << "assimp-testmodels not installed";
  int read = 0, rejected = 0;
  for (const char* sub : {"PLY", "STL"}) {
    for (const auto& entry : std::filesystem::directory_iterator(corpus / sub)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".ply" && ext != ".stl") continue;
      SCOPED_TRACE(entry.path().string());
      try {
        const SurfaceMesh m = readSurface(entry.path());
        EXPECT_GT(m.triangleCount(), 0);
        ++read;
      } catch (const Error& e) {
        EXPECT_EQ(e.file(), entry.path().string());
        ++rejected;
      }
    }
  }
  std::printf("PLY/STL corpus: %d read, %d rejected with an error\n", read, rejected);
  EXPECT_GT(read, 3);
}

}  // namespace
}  // namespace tetskin
