// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Each subcommand of `tetskin` registers itself on the app; its callback wires
// module calls together and throws tetskin::Error on bad input.

namespace CLI {
class App;
}

namespace tetskin::cli {

void addInfoCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);
void addBuildCommand(CLI::App& app);
void addBindCommand(CLI::App& app);
void addDeformCommand(CLI::App& app);
void addSimulateCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addProbeCommand(CLI::App& app);

}  // namespace tetskin::cli
