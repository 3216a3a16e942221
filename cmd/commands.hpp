// The subcommands: each registers itself on the CLI11 app and sets the exit status.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace ncv::cmd {

// Exit statuses shared by every subcommand.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitOutOfTolerance = 1;
inline constexpr int kExitBadInput = 2;

// Each command writes its result status here (0 unless it says otherwise).
struct CommandContext {
  int exit_status = kExitSuccess;
  std::string command_line;  // as typed, for the reports' traceability
};

// argv as one line a shell would read back: arguments with blanks or quotes single-quoted.
std::string quoted_command_line(int argc, char** argv);

void add_sample_command(CLI::App& app, CommandContext& context);
void add_inspect_command(CLI::App& app, CommandContext& context);
void add_grid_build_command(CLI::App& app, CommandContext& context);
void add_distance_command(CLI::App& app, CommandContext& context);
void add_stats_command(CLI::App& app, CommandContext& context);
void add_colorize_command(CLI::App& app, CommandContext& context);
void add_run_command(CLI::App& app, CommandContext& context);
void add_report_command(CLI::App& app, CommandContext& context);

}  // namespace ncv::cmd
