// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/RecordedRun.h"

#include <regex>
#include <utility>

#include "tetskin/core/Error.h"

namespace tetskin {

RecordedRun::RecordedRun(const std::filesystem::path& pvd) : path_(pvd) {
  const PvdSeries series = PvdSeries::read(pvd);
  frames_ = series.framesOfPart(0);
  // A run of several bodies (RunRecorder: control_NNNNN_K.vtu per body) is
  // no run of one level's nodes.
  static const std::regex bodyFrame(R"(control_\d{5}_\d+\.vtu)");
  if (std::regex_match(std::filesystem::path(frames_.front().file).filename().string(), bodyFrame))
    throw Error(pvd.string(), 0,
                "records a scene of several bodies (each body's parts of its own); it replays "
                "in ParaView, not here");
  SimulationFrameFacts facts = simulationFrameFacts(frames_.front().file);
  level_ = facts.level;
  conditions_ = std::move(facts.conditions);
  // (Not checked to be there: only a caller that opens it needs it, and
  // that names it when it is missing.)
  const PvdSeries::Entry* first = nullptr;
  for (const PvdSeries::Entry& entry : series.entries())
    if (entry.part == 1 && (!first || entry.time < first->time)) first = &entry;
  if (first) surface_ = (pvd.parent_path() / first->file).string();
}

double RecordedRun::meanFrameSeconds() const {
  const std::size_t n = frames_.size();
  return n < 2 ? 0 : (frames_.back().time - frames_.front().time) / static_cast<double>(n - 1);
}

FrameState RecordedRun::read(std::size_t frame, const TetMesh& rest,
                             const std::string& restName) const {
  return readSimulationFrame(file(frame), rest, restName);
}

}  // namespace tetskin
