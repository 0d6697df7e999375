// SPDX-License-Identifier: AGPL-3.0-or-later
#include "FuzzChecks.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/DatasetConfig.h"
#include "tetskin/io/GmshFormat.h"
#include "tetskin/io/LoadCurveFile.h"
#include "tetskin/io/MeditFormat.h"
#include "tetskin/io/NodeList.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/io/PlyFormat.h"
#include "tetskin/io/PointList.h"
#include "tetskin/io/TetGenFormat.h"
#include "tetskin/vtkio/BindingFile.h"
#include "tetskin/vtkio/PvdSeries.h"
#include "tetskin/vtkio/SurfaceFile.h"

namespace tetskin::fuzz {
namespace {

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "invariant broken: %s\n", what.c_str());
  std::abort();
}

void require(bool holds, const std::string& what) {
  if (!holds) broken(what);
}

std::string_view text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A scratch file of this process (fuzzers run several processes at once).
std::filesystem::path scratch(const std::string& name) {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("tetskin_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir / name;
}

std::filesystem::path written(const std::string& name, std::string_view content) {
  const std::filesystem::path path = scratch(name);
  std::ofstream(path, std::ios::binary)
      .write(content.data(), static_cast<std::streamsize>(content.size()));
  return path;
}

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

template <typename Matrix>
void requireFinite(const Matrix& m, const char* what) {
  require(m.allFinite(), std::string(what) + " not finite");
}

template <typename Indices>
void requireIndices(const Indices& ids, long long count, const char* what) {
  for (Eigen::Index i = 0; i < ids.size(); ++i)
    require(ids.data()[i] >= 0 && ids.data()[i] < count,
            std::string(what) + " index " + std::to_string(ids.data()[i]) + " outside [0, " +
                std::to_string(count) + ")");
}

void requireSurface(const SurfaceMesh& s) {
  requireFinite(s.positions, "surface positions");
  requireFinite(s.normals, "surface normals");
  requireFinite(s.texcoords, "surface texture coordinates");
  requireIndices(s.triangles, s.positions.rows(), "triangle");
}

void requireSameSurface(const SurfaceMesh& a, const SurfaceMesh& b, const char* format) {
  require(a.positions == b.positions && a.triangles == b.triangles && a.normals == b.normals &&
              a.texcoords == b.texcoords,
          std::string(format) + " round trip differs");
}

// Runs `read`: an Error is a clean refusal (true: accepted).
template <typename Read>
bool accepted(Read&& read) {
  try {
    read();
    return true;
  } catch (const Error&) {
    return false;
  }
}

void checkObj(const std::uint8_t* data, std::size_t size) {
  SurfaceMesh mesh;
  if (!accepted([&] { mesh = parseObj(text(data, size), "fuzz.obj"); })) return;
  requireSurface(mesh);
  writeObj(scratch("round.obj"), mesh);
  requireSameSurface(mesh, readObj(scratch("round.obj")), "OBJ");
}

void checkPly(const std::uint8_t* data, std::size_t size) {
  SurfaceMesh mesh;
  if (!accepted([&] { mesh = parsePly(text(data, size), "fuzz.ply"); })) return;
  requireSurface(mesh);
  writePly(scratch("round.ply"), mesh);
  requireSameSurface(mesh, readPly(scratch("round.ply")), "PLY");
}

// The first byte chooses the file kind: .node, .ele, .face or .poly.
void checkTetGen(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const std::string_view content = text(data + 1, size - 1);
  switch (data[0] % 4) {
    case 0: {
      NodeFile file;
      if (!accepted([&] { file = parseNode(content, "fuzz.node"); })) return;
      requireFinite(file.points, "node coordinates");
      requireFinite(file.attributes, "node attributes");
      writeNode(scratch("round.node"), file);
      const NodeFile back = readNode(scratch("round.node"));
      require(back.points == file.points && back.attributes == file.attributes &&
                  back.markers == file.markers,
              ".node round trip differs");
      return;
    }
    case 1: {
      EleFile file;
      if (!accepted([&] { file = parseEle(content, "fuzz.ele"); })) return;
      requireIndices(file.elements, 1LL << 31, "element node");
      requireFinite(file.attributes, "element attributes");
      writeEle(scratch("round.ele"), file);
      const EleFile back = readEle(scratch("round.ele"));
      require(back.elements == file.elements && back.attributes == file.attributes,
              ".ele round trip differs");
      return;
    }
    case 2: {
      FaceFile file;
      if (!accepted([&] { file = parseFace(content, "fuzz.face"); })) return;
      requireIndices(file.faces, 1LL << 31, "face node");
      writeFace(scratch("round.face"), file);
      const FaceFile back = readFace(scratch("round.face"));
      require(back.faces == file.faces && back.markers == file.markers, ".face round trip differs");
      return;
    }
    default: {
      PolyFile file;
      if (!accepted([&] { file = parsePoly(content, "fuzz.poly"); })) return;
      requireFinite(file.nodes.points, "poly nodes");
      for (const PolyFacet& facet : file.facets)
        for (const std::vector<int>& polygon : facet.polygons)
          for (int id : polygon)
            if (!file.nodesInSeparateFile)
              require(id >= 0 && id < file.nodes.points.rows(), "poly facet index in range");
      return;
    }
  }
}

void checkGmsh(const std::uint8_t* data, std::size_t size) {
  GmshTetrahedra read;
  if (!accepted([&] { read = parseGmshTetrahedra(text(data, size), "fuzz.msh"); })) return;
  requireFinite(read.mesh.nodes, "Gmsh node coordinates");
  requireIndices(read.mesh.elements, read.mesh.nodeCount(), "Gmsh tetrahedron");
  require(static_cast<Index>(read.elementTags.size()) == read.mesh.elementCount(),
          "one tag per Gmsh tetrahedron");
}

void checkMedit(const std::uint8_t* data, std::size_t size) {
  MeditMesh mesh;
  if (!accepted([&] { mesh = parseMedit(text(data, size), "fuzz.mesh"); })) return;
  requireFinite(mesh.vertices, "MEDIT vertices");
  requireIndices(mesh.triangles, mesh.vertices.rows(), "MEDIT triangle");
  requireIndices(mesh.tetrahedra, mesh.vertices.rows(), "MEDIT tetrahedron");
  writeMedit(scratch("round.mesh"), mesh);
  const MeditMesh back = readMedit(scratch("round.mesh"));
  require(back.vertices == mesh.vertices && back.triangles == mesh.triangles &&
              back.tetrahedra == mesh.tetrahedra,
          "MEDIT round trip differs");
}

// Written, read and written again: the same text (the writer keeps what
// the reader took).
void checkConfig(const std::uint8_t* data, std::size_t size) {
  DatasetConfig config;
  if (!accepted([&] {
        config = parseDatasetConfig(text(data, size), "fuzz.json", scratch(".").parent_path());
      }))
    return;
  writeDatasetConfig(scratch("round.json"), config);
  const std::string once = contents(scratch("round.json"));
  writeDatasetConfig(scratch("round2.json"), readDatasetConfig(scratch("round.json")));
  require(contents(scratch("round2.json")) == once, "dataset config round trip differs");
}

void checkLoadCurve(const std::uint8_t* data, std::size_t size) {
  LoadCurve curve;
  if (!accepted([&] { curve = readLoadCurve(written("fuzz_curve.txt", text(data, size))); }))
    return;
  for (double t : {-1.0, 0.0, 0.5, 1e3})
    require(std::isfinite(curve.factorAt(t)), "load curve factor not finite");
}

// The node files of a level of 1000 nodes: --fixed-nodes, --loads,
// --load-faces (face sets) and probe's --points; the first byte chooses
// which.
void checkNodeList(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const std::filesystem::path path = written("fuzz_nodes.txt", text(data + 1, size - 1));
  constexpr Index kNodes = 1000;
  switch (data[0] % 4) {
    case 0: {
      std::vector<int> nodes;
      if (!accepted([&] { nodes = readNodeList(path, kNodes); })) return;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        require(nodes[i] >= 0 && nodes[i] < kNodes, "listed node in range");
        require(i == 0 || nodes[i - 1] < nodes[i], "node list sorted, each once");
      }
      return;
    }
    case 1: {
      Points3 forces;
      if (!accepted([&] { forces = readNodeForces(path, kNodes); })) return;
      require(forces.rows() == kNodes, "a force per node");
      requireFinite(forces, "node forces");
      return;
    }
    case 2: {
      std::vector<FaceSetLine> faces;
      if (!accepted([&] { faces = readFaceSet(path, kNodes); })) return;
      require(!faces.empty(), "a face set has faces");
      for (const FaceSetLine& face : faces)
        for (int node : face.nodes) require(node >= 0 && node < kNodes, "face node in range");
      return;
    }
    default: {
      PointList points;
      if (!accepted([&] { points = readPointList(path); })) return;
      require(points.points.rows() > 0 &&
                  static_cast<std::size_t>(points.points.rows()) == points.lines.size(),
              "a point per line named");
      requireFinite(points.points, "points");
    }
  }
}

// A time series: every entry with a file and a finite time, and the series
// written again reads back the same.
void checkPvd(const std::uint8_t* data, std::size_t size) {
  std::vector<PvdSeries::Entry> entries;
  if (!accepted(
          [&] { entries = PvdSeries::read(written("fuzz.pvd", text(data, size))).entries(); }))
    return;
  PvdSeries again(scratch("round.pvd"));
  for (const PvdSeries::Entry& e : entries) {
    require(std::isfinite(e.time) && !e.file.empty(), "a series entry with a file and a time");
    again.add(e.time, e.part, e.file);
  }
  again.write();
  const std::vector<PvdSeries::Entry> back = PvdSeries::read(scratch("round.pvd")).entries();
  require(back.size() == entries.size(), "series round trip: entries lost");
  for (std::size_t i = 0; i < back.size(); ++i)
    require(back[i].time == entries[i].time && back[i].part == entries[i].part &&
                back[i].file == entries[i].file,
            "series round trip differs at entry " + std::to_string(i));
}

// STL through our adapter over VTK's reader (ASCII or binary: the reader
// tells them apart): what it accepts is a surface that holds up, and its
// triangles round-trip through our STL writer (STL keeps no shared
// vertices and floats only: compared as the surface written, read twice).
void checkStl(const std::uint8_t* data, std::size_t size) {
  SurfaceMesh mesh;
  if (!accepted([&] { mesh = readSurface(written("fuzz.stl", text(data, size))); })) return;
  requireSurface(mesh);
  writeSurface(scratch("round.stl"), mesh);
  const SurfaceMesh once = readSurface(scratch("round.stl"));
  requireSurface(once);
  require(once.triangles.rows() == mesh.triangles.rows(), "STL round trip: triangles lost");
  writeSurface(scratch("round2.stl"), once);
  requireSameSurface(once, readSurface(scratch("round2.stl")), "STL");
}

// The control mesh a fuzzed binding is checked against: one level of 2x2x2
// cubes, 27 nodes.
const MultiLevelTetMesh& bindingDataset() {
  static const MultiLevelTetMesh mesh = [] {
    MultiLevelTetMesh m;
    appendLevel(m, test::tetGrid(2, 2, 2, {1, 1, 1}));
    return m;
  }();
  return mesh;
}

// A .vtp as the applications open it (readSurfaceOrBinding: a plain
// surface, or a binding file, then checked against a dataset as `deform`
// and the GUI check it). A surface accepted holds up and round-trips; a
// binding that fits has every vertex bound to nodes of the level with
// finite weights, and round-trips through writeBinding.
void checkVtp(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path path = written("fuzz.vtp", text(data, size));
  SurfaceOrBinding read;
  if (!accepted([&] { read = readSurfaceOrBinding(path); })) return;
  requireSurface(read.surface);
  if (!read.binding) {
    writeSurface(scratch("round.vtp"), read.surface);
    requireSameSurface(read.surface, readSurface(scratch("round.vtp")), "VTP");
    return;
  }
  const MultiLevelTetMesh& dataset = bindingDataset();
  if (!accepted([&] {
        checkBindingFits(*read.binding, read.surface.vertexCount(), dataset, "fuzz.vtp");
      }))
    return;
  const SurfaceBinding& b = *read.binding;
  require(b.controlIds.rows() == read.surface.vertexCount(), "a binding row per vertex");
  requireIndices(b.controlIds.leftCols(b.controlsPerVertex()).eval(), dataset.nodes.rows(),
                 "bound control node");
  requireFinite(b.weights, "binding weights");
  BoundSurface bound{read.surface, b, "dataset.json", std::nullopt};
  writeBinding(scratch("round_binding.vtp"), bound);
  const BoundSurface back = readBinding(scratch("round_binding.vtp"), dataset);
  require(back.binding.controlIds == b.controlIds && back.binding.weights == b.weights &&
              back.surface.positions == read.surface.positions &&
              back.surface.triangles == read.surface.triangles,
          "binding round trip differs");
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {{"obj", checkObj},
                                          {"ply", checkPly},
                                          {"tetgen", checkTetGen},
                                          {"gmsh", checkGmsh},
                                          {"medit", checkMedit},
                                          {"config", checkConfig},
                                          {"load_curve", checkLoadCurve},
                                          {"node_list", checkNodeList},
                                          {"pvd", checkPvd},
                                          {"stl", checkStl},
                                          {"vtp", checkVtp}};
  return all;
}

Check checkOf(const std::string& name) {
  for (const Target& t : targets())
    if (name == t.name) return t.check;
  return nullptr;
}

}  // namespace tetskin::fuzz
