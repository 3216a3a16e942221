// ncverify stats DIST: error measures against a tolerance, as text, JSON or CSV; exit
// status 1 when out of tolerance.
#include <unistd.h>

#include "commands.hpp"
#include "option_groups.hpp"
#include "options.hpp"

namespace ncv::cmd {

void add_stats_command(CLI::App& app, CommandContext& context) {
  auto job = std::make_shared<StatsJob>();
  CLI::App* sub = app.add_subcommand(
      "stats", "Error measures of a distance file; exit 1 when out of tolerance");
  sub->add_option(
      "distances", job->distances,
      "Distance file from `distance` (- or none: standard input), and optionally the same part's "
      "reverse distance file (`distance --reverse`); or every shard's of each");
  add_samples_file_option(*sub, job->samples);
  add_enum_option(*sub, "--format", job->format, kReportFormatNames, "Report format");
  sub->add_flag(
      "--no-header", [job](std::int64_t) { job->csv_header = false; },
      "CSV: only the row (to append to a table)");
  sub->add_flag("--csv-header", job->csv_header_only,
                "Only print the CSV header line (to start a table of many parts)");
  sub->add_option("-o,--output", job->output, "Report file (default: standard output)");
  add_tolerance_option(
      *sub, job->options.tolerance,
      "Tolerance zone LOWER:UPPER (e.g. -0.05:0.1), or T for ±T; out of it, exit 1");
  add_report_options(*sub, job->options);
  add_one_sided_option(*sub, job->options);
  sub->add_option("--histogram-svg", job->files.histogram_svg,
                  "Also draw the area-weighted histogram as SVG");
  add_report_file_options(*sub, job->files);
  sub->callback([job, &context] {
    job->command_line = context.command_line;
    // No file named: standard input, as `-` reads it, unless it is a terminal (nobody
    // types a binary file).
    if (job->distances.empty() && !job->csv_header_only) {
      if (::isatty(STDIN_FILENO)) {
        throw UsageError(
            "stats: give a distance file, or pipe one in (`distance ... -o - | stats`)");
      }
      job->distances.push_back("-");
    }
    context.exit_status = run_stats(*job);
  });
}

}  // namespace ncv::cmd
