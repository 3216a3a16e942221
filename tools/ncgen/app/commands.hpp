// The ncgen subcommands: each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>

namespace ncv::gen::app {

struct GlobalOptions {
  std::uint64_t seed = 1;  // shapes the mould core's freeform crown
};

void add_nominal_command(CLI::App& app, const GlobalOptions& global);
void add_workpiece_command(CLI::App& app, const GlobalOptions& global);
void add_box_command(CLI::App& app);
void add_scallop_command(CLI::App& app);
void add_all_command(CLI::App& app, const GlobalOptions& global);

}  // namespace ncv::gen::app
