// SPDX-License-Identifier: AGPL-3.0-or-later
// tetskin: the command-line front end. Parses, wires modules, reports; no math.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>

#include "Commands.h"
#include "tetskin/core/Error.h"

namespace {

// "tetskin" or "tetskin SUBCOMMAND", as far as the command line named one.
std::string commandPath(const CLI::App& app) {
  std::string path = app.get_name();
  for (const CLI::App* sub : app.get_subcommands()) path += " " + sub->get_name();
  return path;
}

std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text;
}

// CLI11's words for an option given more than once ("--steps: At Most 1
// required but received 2") and for a list option given too few or too many
// values ("--gravity: At least 3 required but received 2") in ours.
std::string plainUsageError(const std::string& text) {
  static const std::regex repeated("At Most 1 required but received ([0-9]+)");
  static const std::regex valueCount("At (least|Most) ([0-9]+) required but received ([0-9]+)");
  return std::regex_replace(std::regex_replace(text, repeated, "given $1 times; give it once"),
                            valueCount, "takes $2 values, got $3");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "TetSkin: a coarse tetrahedral control mesh simulated in real time, with a\n"
      "high-resolution surface bound to it (and optional fur).",
      "tetskin"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "tetskin " TETSKIN_VERSION);
  tetskin::cli::addBuildCommand(app);
  tetskin::cli::addBindCommand(app);
  tetskin::cli::addDeformCommand(app);
  tetskin::cli::addSimulateCommand(app);
  tetskin::cli::addCompareCommand(app);
  tetskin::cli::addRenderCommand(app);
  tetskin::cli::addBenchCommand(app);
  tetskin::cli::addProbeCommand(app);
  tetskin::cli::addInfoCommand(app);
  tetskin::cli::addConvertCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0: CLI11 prints them.
    if (e.get_exit_code() == 0) return app.exit(e);
    // A usage error is bad input like any other: one line, status 1.
    std::cerr << "error: " << plainUsageError(oneLine(e.what())) << " (see " << commandPath(app)
              << " --help)\n";
    return 1;
  } catch (const tetskin::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // e.g. a folder to create where a file is: the path and the reason.
    std::cerr << "error: " << e.path1().string() << ": " << e.code().message() << '\n';
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
