// Parse errors in a user's words: an unknown command or option gets the nearest valid one
// suggested, a missing value names its option. The rest are CLI11's own messages.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ncv::cmd {

// The message for an unknown subcommand in `args` (argv without the program), checked before
// parsing: CLI11 would only say that a subcommand is required. Nothing when the first
// argument that is not a global option names a subcommand, or there is none.
std::optional<std::string> unknown_command(const CLI::App& app,
                                           const std::vector<std::string>& args);

// The message for a parse error of `app` on `args`.
std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app,
                                const std::vector<std::string>& args);

}  // namespace ncv::cmd
