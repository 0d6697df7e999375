// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/RunRecorder.h"

#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <cstdio>
#include <regex>
#include <utility>

#include "tetskin/core/Error.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkConversion.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

std::filesystem::path withPvdExtension(std::filesystem::path p) {
  if (lowerExtension(p) != ".pvd") p += ".pvd";
  return p;
}

// `body`'s part of the run's conditions: its prescribed nodes, numbered
// from its first.
RunConditions bodyPart(const RunConditions& conditions, const BodyRange& body) {
  RunConditions part{conditions.floor, {}};
  for (int node : conditions.prescribedNodes)
    if (node >= body.firstNode && node < body.firstNode + body.nodeCount)
      part.prescribedNodes.push_back(node - static_cast<int>(body.firstNode));
  return part;
}

// `body`'s part of a deformed surface: its skin, binding and moved state.
BoundSurface bodyPart(const BoundSurface& surface, const BodyRange& body) {
  BoundSurface part;
  part.surface = bodyPart(surface.surface, body);
  part.binding = bodyPart(surface.binding, body);
  part.dataset = surface.dataset;
  if (surface.deformed) {
    const DeformedState& from = *surface.deformed;
    const auto rows = [&](const Points3& all) -> Points3 {
      return all.rows() == 0 ? all : Points3(all.middleRows(body.firstVertex, body.vertexCount));
    };
    DeformedState& to = part.deformed.emplace();
    to.positions = rows(from.positions);
    to.normals = rows(from.normals);
    for (const PointScalars& s : from.scalars)
      to.scalars.push_back({s.name, s.values.segment(body.firstVertex, body.vertexCount)});
    for (const PointVectors& v : from.vectors) to.vectors.push_back({v.name, rows(v.values)});
  }
  return part;
}

}  // namespace

std::filesystem::path RunRecorder::framesDirectory(const std::filesystem::path& pvd) {
  const std::filesystem::path file = std::filesystem::absolute(withPvdExtension(pvd));
  return file.parent_path() / (file.stem().string() + "_frames");
}

RunRecorder::RunRecorder(std::filesystem::path pvd, RunConditions conditions, int surfacePieces)
    : framesDirectory_(framesDirectory(pvd)),
      series_(withPvdExtension(pvd)),
      conditions_(std::move(conditions)),
      surfacePieces_(surfacePieces) {
  if (surfacePieces < 1)
    throw Error(series_.path().string(), 0,
                "a surface is written in 1 or more pieces, not " + std::to_string(surfacePieces));
  std::filesystem::create_directories(framesDirectory_);
  // A run written under the name of an earlier one replaces it. The earlier
  // frames would otherwise stay beside the new ones, in one numbered
  // sequence with them (control_00000.vtu ...), which file dialogs such as
  // ParaView's offer as one series. Only files named as this class names
  // frames go, and the old .pvd, which names them.
  static const std::regex frameName(
      R"((control_\d{5}(_\d+)?\.vtu|surface_\d{5}(_\d+)?(\.vtp|\.pvtp|_piece\d+\.vtp)|obstacle_(\d{5}_)?\d+\.vtp))");
  for (const auto& entry : std::filesystem::directory_iterator(framesDirectory_))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), frameName))
      std::filesystem::remove(entry.path());
  std::filesystem::remove(series_.path());
}

void RunRecorder::addFrame(double time, const TetMesh& rest, const FrameFields& fields, int level,
                           const BoundSurface* deformedSurface,
                           std::span<const PosedSurface> obstacles,
                           std::span<const BodyRange> bodies) {
  char name[64];
  // The series names its files relative to the .pvd, which lies beside the folder.
  const std::string folder = framesDirectory_.filename().string() + "/";
  if (bodies.size() <= 1) {
    std::snprintf(name, sizeof name, "control_%05lld.vtu", static_cast<long long>(frames_));
    writeVtu(framesDirectory_ / name, simulationFrame(rest, fields, level, conditions_));
    series_.add(time, 0, folder + name);
    if (deformedSurface) addSurface(time, *deformedSurface);
  } else {
    const BodyRange& last = bodies.back();
    if (rest.nodeCount() != last.firstNode + last.nodeCount ||
        (deformedSurface &&
         deformedSurface->surface.vertexCount() != last.firstVertex + last.vertexCount))
      throw Error(series_.path().string(), 0,
                  "the frame's mesh or surface is not the union of its " +
                      std::to_string(bodies.size()) + " bodies");
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const BodyRange& body = bodies[b];
      std::snprintf(name, sizeof name, "control_%05lld_%zu.vtu", static_cast<long long>(frames_),
                    b);
      writeVtu(framesDirectory_ / name,
               simulationFrame(bodyPart(rest, body), bodyPart(fields, body), level,
                               bodyPart(conditions_, body)));
      const int part = 2 * static_cast<int>(b);
      series_.add(time, part, folder + name);
      if (!deformedSurface) continue;
      char stem[64];
      std::snprintf(stem, sizeof stem, "surface_%05lld_%zu", static_cast<long long>(frames_), b);
      writeSurface(time, part + 1, stem, bodyPart(*deformedSurface, body));
    }
  }
  const int firstObstacle = firstObstaclePart(static_cast<int>(bodies.size()));
  for (std::size_t k = 0; k < obstacles.size(); ++k)
    addObstacle(time, firstObstacle + static_cast<int>(k), k, obstacles[k]);
  series_.write();
  ++frames_;
}

void RunRecorder::addObstacle(double time, int part, std::size_t k, const PosedSurface& obstacle) {
  char name[64];
  if (obstacle.moves)
    std::snprintf(name, sizeof name, "obstacle_%05lld_%zu.vtp", static_cast<long long>(frames_), k);
  else
    std::snprintf(name, sizeof name, "obstacle_%zu.vtp", k);
  if (staticObstacleWritten_.size() <= k) staticObstacleWritten_.resize(k + 1, false);
  if (obstacle.moves || !staticObstacleWritten_[k]) {
    SurfaceMesh posed = *obstacle.surface;
    for (Index v = 0; v < posed.positions.rows(); ++v)
      posed.positions.row(v) = (obstacle.toWorld * posed.positions.row(v).transpose()).transpose();
    posed.normals.resize(0, 3);  // (flat shading; the scale would stretch them)
    writeVtp(framesDirectory_ / name, toVtkPolyData(posed));
    staticObstacleWritten_[k] = !obstacle.moves;
  }
  series_.add(time, part, framesDirectory_.filename().string() + "/" + name);
}

void RunRecorder::addSurfaceFrame(double time, const BoundSurface& deformedSurface) {
  addSurface(time, deformedSurface);
  series_.write();
  ++frames_;
}

void RunRecorder::addSurfacesFrame(double time,
                                   const std::vector<const BoundSurface*>& deformedSurfaces) {
  for (std::size_t part = 0; part < deformedSurfaces.size(); ++part) {
    char stem[64];
    std::snprintf(stem, sizeof stem, "surface_%05lld_%zu", static_cast<long long>(frames_), part);
    writeSurface(time, static_cast<int>(part), stem, *deformedSurfaces[part]);
  }
  series_.write();
  ++frames_;
}

void RunRecorder::addSurface(double time, const BoundSurface& deformedSurface) {
  char stem[64];
  std::snprintf(stem, sizeof stem, "surface_%05lld", static_cast<long long>(frames_));
  writeSurface(time, 1, stem, deformedSurface);
}

void RunRecorder::writeSurface(double time, int part, const std::string& stem,
                               const BoundSurface& surface) {
  const std::string name = stem + (surfacePieces_ > 1 ? ".pvtp" : ".vtp");
  if (surfacePieces_ == 1) {
    writeBinding(framesDirectory_ / name, surface);
  } else {
    if (piecesOfPart_.size() <= static_cast<std::size_t>(part))
      piecesOfPart_.resize(static_cast<std::size_t>(part) + 1);
    std::vector<SurfacePiece>& pieces = piecesOfPart_[static_cast<std::size_t>(part)];
    if (pieces.empty()) pieces = restPieces(surface, surfacePieces_);
    writeBinding(framesDirectory_ / name, surface, pieces);
  }
  series_.add(time, part, framesDirectory_.filename().string() + "/" + name);
}

}  // namespace tetskin
