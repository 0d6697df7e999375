// SPDX-License-Identifier: AGPL-3.0-or-later
// Subcommands of the product contract (shared/design/PRODUCT.md) whose module
// has not landed yet. They are listed in --help so scripts can discover them,
// and refuse to run with a clear message instead of pretending to work.
#include <CLI/CLI.hpp>

#include "Commands.h"
#include "tetskin/core/Error.h"

namespace tetskin::cli {

void addPendingCommands(CLI::App& app) {
  struct Pending {
    const char* name;
    const char* description;
  };
  static const Pending pending[] = {
      {"render", "Headless rendering of a dataset and surface (not available yet)"},
      {"bench", "Reproduce the report's Table 6.1 (not available yet)"},
  };
  for (const Pending& p : pending) {
    CLI::App* cmd = app.add_subcommand(p.name, p.description);
    cmd->allow_extras();
    const std::string name = p.name;
    cmd->callback(
        [name] { throw Error("'tetskin " + name + "' is not available in this build yet"); });
  }
}

}  // namespace tetskin::cli
