// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin: the command-line front end. Parses, wires modules, reports; no math.
#include <CLI/CLI.hpp>
#include <iostream>

#include "Commands.h"
#include "tetskin/core/Error.h"

int main(int argc, char** argv) {
  CLI::App app{
      "TetSkin: a coarse tetrahedral control mesh simulated in real time, with a\n"
      "high-resolution surface bound to it (and optional fur).",
      "tetskin"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "tetskin 0.1.0");
  tetskin::cli::addBuildCommand(app);
  tetskin::cli::addBindCommand(app);
  tetskin::cli::addDeformCommand(app);
  tetskin::cli::addSimulateCommand(app);
  tetskin::cli::addRenderCommand(app);
  tetskin::cli::addBenchCommand(app);
  tetskin::cli::addInfoCommand(app);
  tetskin::cli::addConvertCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const tetskin::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
