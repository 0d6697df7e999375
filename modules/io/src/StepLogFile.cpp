// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/StepLogFile.h"

#include <cstdio>
#include <ostream>

#include "tetskin/io/AtomicFile.h"

namespace tetskin {
namespace {

// Enough digits for a plot and for telling close energies apart.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

}  // namespace

std::string stepLogHeader() {
  return "step,time_s,solver,iterations,relative_residual,contacts,assembly_ms,setup_ms,"
         "solve_ms,step_ms,kinetic_J,elastic_J,gravitational_J,load_J,total_J,reaction_x_N,"
         "reaction_y_N,"
         "reaction_z_N";
}

void writeStepLog(const std::filesystem::path& path, const std::vector<StepLogRow>& rows) {
  writeTextAtomically(path, [&](std::ostream& out) {
    out << stepLogHeader() << '\n';
    for (const StepLogRow& r : rows) {
      out << r.step << ',' << number(r.time) << ',';
      if (r.step == 0)
        out << ",,,,,,,,";
      else
        out << r.solver << ',' << r.iterations << ',' << number(r.residual) << ',' << r.contacts
            << ',' << number(1e3 * r.assemblySeconds) << ',' << number(1e3 * r.setupSeconds) << ','
            << number(1e3 * r.solveSeconds) << ',' << number(1e3 * r.stepSeconds) << ',';
      out << number(r.kinetic) << ',' << number(r.elastic) << ',' << number(r.gravitational) << ','
          << number(r.load) << ',' << number(r.kinetic + r.elastic + r.gravitational + r.load)
          << ',' << number(r.reaction.x()) << ',' << number(r.reaction.y()) << ','
          << number(r.reaction.z()) << '\n';
    }
  });
}

}  // namespace tetskin
