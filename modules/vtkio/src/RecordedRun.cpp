// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/RecordedRun.h"

namespace tetskin {

RecordedRun::RecordedRun(const std::filesystem::path& pvd)
    : path_(pvd), frames_(PvdSeries::read(pvd).framesOfPart(0)) {
  level_ = simulationFrameLevel(frames_.front().file);
}

FrameState RecordedRun::read(std::size_t frame, const TetMesh& rest,
                             const std::string& restName) const {
  return readSimulationFrame(file(frame), rest, restName);
}

}  // namespace tetskin
