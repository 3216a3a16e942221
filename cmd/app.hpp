// The ncverify command line: every subcommand on one CLI11 app, parse errors and failures
// mapped to one line on stderr and the exit status (commands.hpp). main() and the command-line
// fuzzer (fuzz/fuzz_command_line.cpp) call it.
#pragma once

namespace ncv::cmd {

// Runs the command line `argv` (argv[0] the program) and returns the exit status.
int run_ncverify(int argc, char** argv);

}  // namespace ncv::cmd
