// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/RunRecorder.h"

#include <vtkUnstructuredGrid.h>

#include <cstdio>
#include <regex>
#include <utility>

#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/SimulationFrame.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {
namespace {

std::filesystem::path withPvdExtension(std::filesystem::path p) {
  if (lowerExtension(p) != ".pvd") p += ".pvd";
  return p;
}

}  // namespace

std::filesystem::path RunRecorder::framesDirectory(const std::filesystem::path& pvd) {
  const std::filesystem::path file = std::filesystem::absolute(withPvdExtension(pvd));
  return file.parent_path() / (file.stem().string() + "_frames");
}

RunRecorder::RunRecorder(std::filesystem::path pvd, RunConditions conditions)
    : framesDirectory_(framesDirectory(pvd)),
      series_(withPvdExtension(pvd)),
      conditions_(std::move(conditions)) {
  std::filesystem::create_directories(framesDirectory_);
  // A run written under the name of an earlier one replaces it. The earlier
  // frames would otherwise stay beside the new ones, in one numbered
  // sequence with them (control_00000.vtu ...), which file dialogs such as
  // ParaView's offer as one series. Only files named as this class names
  // frames go, and the old .pvd, which names them.
  static const std::regex frameName(R"((control_\d{5}\.vtu|surface_\d{5}(_\d+)?\.vtp))");
  for (const auto& entry : std::filesystem::directory_iterator(framesDirectory_))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), frameName))
      std::filesystem::remove(entry.path());
  std::filesystem::remove(series_.path());
}

void RunRecorder::addFrame(double time, const TetMesh& rest, const FrameFields& fields, int level,
                           const BoundSurface* deformedSurface) {
  char name[64];
  std::snprintf(name, sizeof name, "control_%05lld.vtu", static_cast<long long>(frames_));
  // The series names its files relative to the .pvd, which lies beside the folder.
  const std::string folder = framesDirectory_.filename().string() + "/";
  writeVtu(framesDirectory_ / name, simulationFrame(rest, fields, level, conditions_));
  series_.add(time, 0, folder + name);
  if (deformedSurface) addSurface(time, *deformedSurface);
  series_.write();
  ++frames_;
}

void RunRecorder::addSurfaceFrame(double time, const BoundSurface& deformedSurface) {
  addSurface(time, deformedSurface);
  series_.write();
  ++frames_;
}

void RunRecorder::addSurfacesFrame(double time,
                                   const std::vector<const BoundSurface*>& deformedSurfaces) {
  for (std::size_t part = 0; part < deformedSurfaces.size(); ++part) {
    char name[64];
    std::snprintf(name, sizeof name, "surface_%05lld_%zu.vtp", static_cast<long long>(frames_),
                  part);
    writeBinding(framesDirectory_ / name, *deformedSurfaces[part]);
    series_.add(time, static_cast<int>(part), framesDirectory_.filename().string() + "/" + name);
  }
  series_.write();
  ++frames_;
}

void RunRecorder::addSurface(double time, const BoundSurface& deformedSurface) {
  char name[64];
  std::snprintf(name, sizeof name, "surface_%05lld.vtp", static_cast<long long>(frames_));
  writeBinding(framesDirectory_ / name, deformedSurface);
  series_.add(time, 1, framesDirectory_.filename().string() + "/" + name);
}

}  // namespace tetskin
