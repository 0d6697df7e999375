// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/PvdSeries.h"

#include <iomanip>

#include "tetskin/io/AtomicFile.h"

namespace tetskin {

PvdSeries::PvdSeries(std::filesystem::path pvdPath) : path_(std::move(pvdPath)) {}

void PvdSeries::add(double time, int part, const std::string& file) {
  entries_.push_back({time, part, file});
}

void PvdSeries::write() const {
  writeTextAtomically(path_, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const Entry& e : entries_)
      out << "    <DataSet timestep=\"" << std::setprecision(17) << e.time
          << "\" group=\"\" part=\"" << e.part << "\" file=\"" << e.file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace tetskin
