// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/RecordedRun.h"

#include <regex>
#include <utility>

#include "tetskin/core/Error.h"
#include "tetskin/core/NumberText.h"

namespace tetskin {
namespace {

// Body k's control frames in a run of several bodies are named
// control_NNNNN_k.vtu (RunRecorder); a run of one body's control_NNNNN.vtu.
std::optional<int> bodyOfFrame(const std::string& file) {
  static const std::regex bodyFrame(R"(control_\d{5}_(\d+)\.vtu)");
  std::smatch match;
  const std::string name = std::filesystem::path(file).filename().string();
  if (!std::regex_match(name, match, bodyFrame)) return std::nullopt;
  return std::stoi(match[1].str());
}

bool hasPart(const PvdSeries& series, int part) {
  for (const PvdSeries::Entry& entry : series.entries())
    if (entry.part == part) return true;
  return false;
}

}  // namespace

RecordedRun::RecordedRun(const std::filesystem::path& pvd) : path_(pvd) {
  const PvdSeries series = PvdSeries::read(pvd);
  frames_ = series.framesOfPart(0);
  if (bodyOfFrame(frames_.front().file) == 0) {
    // Body k's control mesh is part 2k, as long as the parts say so (the
    // obstacles follow the bodies).
    for (int b = 0; hasPart(series, 2 * b); ++b) {
      std::vector<PvdSeries::Entry> frames = series.framesOfPart(2 * b);
      if (bodyOfFrame(frames.front().file) != b) break;
      if (frames.size() != frames_.size())
        throw Error(pvd.string(), 0,
                    "has " + std::to_string(frames.size()) + " frames of body " +
                        std::to_string(b) + " and " + std::to_string(frames_.size()) +
                        " of body 0: the bodies of a run are recorded together");
      for (std::size_t f = 0; f < frames.size(); ++f)
        if (frames[f].time != frames_[f].time)
          throw Error(pvd.string(), 0,
                      "frame " + std::to_string(f) + " of body " + std::to_string(b) +
                          " is at time " + formatNumber(frames[f].time) + ", body 0's at " +
                          formatNumber(frames_[f].time) +
                          ": the bodies of a run are recorded together");
      bodyFrames_.push_back(std::move(frames));
    }
  }
  if (bodyFrames_.empty()) {
    SimulationFrameFacts facts = simulationFrameFacts(frames_.front().file);
    level_ = facts.level;
    conditions_ = std::move(facts.conditions);
    bodies_.push_back({0, facts.nodeCount, 0, facts.elementCount});
    // (Not checked to be there: only a caller that opens it needs it, and
    // that names it when it is missing.)
    const PvdSeries::Entry* first = nullptr;
    for (const PvdSeries::Entry& entry : series.entries())
      if (entry.part == 1 && (!first || entry.time < first->time)) first = &entry;
    if (first) surface_ = (pvd.parent_path() / first->file).string();
    return;
  }
  // Several bodies: their union's level (one level of them all) and
  // floor are the first body's; the prescribed nodes are every body's,
  // numbered in the union.
  BodyRange at;
  for (std::size_t b = 0; b < bodyFrames_.size(); ++b) {
    SimulationFrameFacts facts = simulationFrameFacts(bodyFrames_[b].front().file);
    if (b == 0) {
      level_ = facts.level;
      conditions_.floor = facts.conditions.floor;
    }
    for (const int node : facts.conditions.prescribedNodes)
      conditions_.prescribedNodes.push_back(node + static_cast<int>(at.firstNode));
    at.nodeCount = facts.nodeCount;
    at.elementCount = facts.elementCount;
    bodies_.push_back(at);
    at.firstNode += at.nodeCount;
    at.firstElement += at.elementCount;
  }
}

double RecordedRun::meanFrameSeconds() const {
  const std::size_t n = frames_.size();
  return n < 2 ? 0 : (frames_.back().time - frames_.front().time) / static_cast<double>(n - 1);
}

TetMesh RecordedRun::rest() const {
  if (bodyFrames_.empty()) return readFrameRest(file(0));
  TetMesh all;
  const BodyRange& last = bodies_.back();
  all.nodes.resize(last.firstNode + last.nodeCount, 3);
  all.elements.resize(last.firstElement + last.elementCount, 4);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodyRange& body = bodies_[b];
    const TetMesh part = readFrameRest(bodyFrames_[b].front().file);
    if (part.nodes.rows() != body.nodeCount || part.elements.rows() != body.elementCount)
      throw Error(bodyFrames_[b].front().file, 0, "changed while the run was read");
    placeBodyPart(part, body, all.nodes, all.elements);
  }
  return all;
}

FrameState RecordedRun::read(std::size_t frame, const TetMesh& rest,
                             const std::string& restName) const {
  if (bodyFrames_.empty()) return readSimulationFrame(file(frame), rest, restName);
  const BodyRange& last = bodies_.back();
  const Index nodes = last.firstNode + last.nodeCount;
  const Index elements = last.firstElement + last.elementCount;
  if (rest.nodes.rows() != nodes || rest.elements.rows() != elements)
    throw Error(
        path_.string(), 0,
        "records " + std::to_string(bodies_.size()) + " bodies of " + std::to_string(nodes) +
            " nodes and " + std::to_string(elements) + " tetrahedra in all; " + restName + " has " +
            std::to_string(rest.nodes.rows()) + " and " + std::to_string(rest.elements.rows()) +
            ": it is read on the scene it was recorded from");
  std::vector<FrameState> parts;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    parts.push_back(readSimulationFrame(bodyFrames_[b].at(frame).file, bodyPart(rest, bodies_[b]),
                                        restName + ", body " + std::to_string(b)));
  FrameState all;
  all.positions.resize(nodes, 3);
  all.velocities.resize(nodes, 3);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodyRange& body = bodies_[b];
    all.positions.middleRows(body.firstNode, body.nodeCount) = parts[b].positions;
    all.velocities.middleRows(body.firstNode, body.nodeCount) = parts[b].velocities;
  }
  // A per-element array comes whole where every body's frame has it, else
  // not at all (as for a frame without it).
  const auto gather = [&](auto member, auto& whole) {
    for (const FrameState& part : parts)
      if ((part.*member).rows() == 0) return;
    whole.resize(elements, whole.cols());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
      whole.middleRows(bodies_[b].firstElement, bodies_[b].elementCount) = parts[b].*member;
  };
  gather(&FrameState::vonMisesStress, all.vonMisesStress);
  gather(&FrameState::equivalentStrain, all.equivalentStrain);
  gather(&FrameState::stress, all.stress);
  return all;
}

}  // namespace tetskin
