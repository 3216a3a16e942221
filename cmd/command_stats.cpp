// ncverify stats DIST: error measures against a tolerance, as text, JSON or CSV; exit
// status 1 when out of tolerance.
#include <spdlog/spdlog.h>

#include <optional>

#include "commands.hpp"
#include "files/distance_file.hpp"
#include "report_options.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace ncv::cmd {
namespace {

struct StatsOptions {
  std::string distances;
  std::string output = "-";
  std::string format = "text";
  ReportOptions report;
  bool no_header = false;
  bool header_only = false;
};

void run_stats(const StatsOptions& options, CommandContext& context) {
  if (options.header_only) {
    OutputFile out(options.output, OutputKind::text);
    out.write(report_csv_header());
    out.commit();
    return;
  }
  if (options.distances.empty()) throw UsageError("stats: give a distance file");
  const DistanceSet distances = read_distance_file(options.distances);
  const PartReport report = make_report(distances, options.report);
  // Both outputs open before either is committed: a histogram path that cannot be
  // written leaves no report either.
  OutputFile out(options.output, OutputKind::text);
  std::optional<OutputFile> histogram;
  if (!options.report.histogram_svg.empty()) {
    histogram.emplace(options.report.histogram_svg, OutputKind::text);
    write_histogram(report, *histogram);
  }
  out.write(format_report(report, parse_report_format(options.format), !options.no_header));
  out.commit();
  if (histogram) histogram->commit();
  context.exit_status = verdict_status(report);
}

}  // namespace

void add_stats_command(CLI::App& app, CommandContext& context) {
  auto options = std::make_shared<StatsOptions>();
  CLI::App* sub = app.add_subcommand(
      "stats", "Error measures of a distance file; exit 1 when out of tolerance");
  sub->add_option("distances", options->distances, "Distance file from `distance` (- = stdin)");
  sub->add_option("--format", options->format, "text, json or csv")
      ->check(CLI::IsMember({"text", "json", "csv"}))
      ->capture_default_str();
  sub->add_flag("--no-header", options->no_header, "CSV: only the row (to append to a table)");
  sub->add_flag("--csv-header", options->header_only,
                "Only print the CSV header line (to start a table of many parts)");
  sub->add_option("-o,--output", options->output, "Report file (default: standard output)");
  add_report_options(*sub, options->report);
  sub->callback([options, &context] { run_stats(*options, context); });
}

}  // namespace ncv::cmd
