// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin probe RUN.pvd --points FILE [-o OUT.csv]: a recorded run's
// displacement and stress at given points, frame by frame, as CSV.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdio>
#include <memory>
#include <ostream>
#include <sstream>

#include "Commands.h"
#include "OptionChecks.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/PointList.h"
#include "tetskin/session/RunProbe.h"

namespace tetskin::cli {
namespace {

// The shortest text that reads back as `value` ("nan" for a frame without
// the value).
std::string number(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

struct ProbeOptions {
  std::filesystem::path run, points, output;
};

void writeTable(std::ostream& out, const RunProbe& probe, const Points3& points) {
  out << "time,point,x,y,z,element,displacement_x,displacement_y,displacement_z,stress_xx,"
         "stress_yy,stress_zz,stress_xy,stress_yz,stress_xz,von_mises\n";
  for (std::size_t f = 0; f < probe.times.size(); ++f)
    for (Index p = 0; p < points.rows(); ++p) {
      out << number(probe.times[f]) << ',' << p;
      for (int axis = 0; axis < 3; ++axis) out << ',' << number(points(p, axis));
      out << ',' << probe.elements[static_cast<std::size_t>(p)];
      for (int axis = 0; axis < 3; ++axis) out << ',' << number(probe.displacements[f](p, axis));
      for (int c = 0; c < 6; ++c)
        out << ',' << (probe.stresses[f].rows() > 0 ? number(probe.stresses[f](p, c)) : "");
      out << ',' << number(probe.vonMises[f][p]) << '\n';
    }
}

}  // namespace

void addProbeCommand(CLI::App& app) {
  auto o = std::make_shared<ProbeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "probe",
      "A recorded run's displacement and stress at given points (the rest shape's "
      "coordinates), in every frame, as CSV: the displacement interpolated in the point's "
      "tetrahedron, the stress its tetrahedron's");
  cmd->add_option("RUN", o->run, "the run's .pvd (tetskin simulate, the GUI's Record)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--points", o->points,
                  "the points: a text file of lines X Y Z (the rest shape's coordinates), # "
                  "comments")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output, "write the table here (.csv) instead of stdout");
  cmd->callback([o] {
    if (!o->output.empty()) requireNotAnInput(o->output, {o->run, o->points});
    const PointList points = readPointList(o->points);
    std::vector<std::string> names;
    for (long line : points.lines) names.push_back(o->points.string() + ":" + std::to_string(line));
    const RunProbe probe = probeRun(o->run, points.points, names);
    if (o->output.empty()) {
      std::ostringstream table;
      writeTable(table, probe, points.points);
      std::fputs(table.str().c_str(), stdout);
      return;
    }
    writeTextAtomically(o->output,
                        [&](std::ostream& out) { writeTable(out, probe, points.points); });
    std::printf("wrote %s (%zu frames x %lld points)\n", o->output.c_str(), probe.times.size(),
                static_cast<long long>(points.points.rows()));
  });
}

}  // namespace tetskin::cli
