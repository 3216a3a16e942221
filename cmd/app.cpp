#include "app.hpp"

#include <spdlog/spdlog.h>

#include <tbb/global_control.h>

#include <exception>
#include <memory>

#include "commands.hpp"
#include "options.hpp"
#include "parse_errors.hpp"
#include "util/error.hpp"
#include "util/logging.hpp"
#include "util/output_file.hpp"

namespace ncv::cmd {

int run_ncverify(int argc, char** argv) {
  CLI::App app{"ncverify: measures how far a machined workpiece mesh is from its nominal part"};
  app.require_subcommand(1);
  app.fallthrough();
  app.set_version_flag("--version", "ncverify " NCV_VERSION);
  bool quiet = false, verbose = false;
  std::uint64_t threads = 0;
  add_count_option(app, "-j,--threads", threads, 0, kMaxThreads,
                   "Worker threads (0: all cores); results do not depend on it");
  std::unique_ptr<tbb::global_control> thread_limit;
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors on standard error");
  app.add_flag("-v,--verbose", verbose, "More detail on standard error");

  CommandContext context;
  context.command_line = quoted_command_line(argc, argv);
  add_sample_command(app, context);
  add_grid_build_command(app, context);
  add_distance_command(app, context);
  add_stats_command(app, context);
  add_colorize_command(app, context);
  add_run_command(app, context);
  add_report_command(app, context);
  add_inspect_command(app, context);

  // Logging must be set up before any subcommand callback runs.
  app.parse_complete_callback([&] {
    setup_logging(quiet ? Verbosity::quiet : (verbose ? Verbosity::verbose : Verbosity::normal));
    if (threads > 0) {
      thread_limit = std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    }
  });
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (const std::optional<std::string> unknown = unknown_command(app, args)) {
      setup_logging(Verbosity::normal);
      spdlog::error("{} (see --help)", *unknown);
      return kExitBadInput;
    }
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print their text and succeed. Any other parse error is bad
    // usage: one line on stderr like every other error (CLI11's own report adds a second).
    if (e.get_exit_code() == 0) return app.exit(e);
    setup_logging(Verbosity::normal);
    spdlog::error("{} (see --help)", parse_error_message(e, app, args));
    return kExitBadInput;
  } catch (const InputError& e) {
    spdlog::error("{}", e.what());
    return kExitBadInput;
  } catch (const UsageError& e) {
    spdlog::error("{}", e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    spdlog::error("out of memory");
    return kExitBadInput;
  } catch (const std::exception& e) {
    // Every expected fault is an InputError or UsageError; this is a bug, but still one
    // line and a clean exit rather than a crash.
    spdlog::error("internal error: {}", e.what());
    return kExitBadInput;
  }
  return context.exit_status;
}

}  // namespace ncv::cmd
